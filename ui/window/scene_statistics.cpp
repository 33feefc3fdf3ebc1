#include "ui/window/scene_statistics.h"

#include <QDialogButtonBox>
#include <QFontDatabase>
#include <QTextEdit>
#include <QTimer>
#include <QVBoxLayout>

namespace trimlab::ui {

namespace {

/// Milliseconds a burst of content changes is gathered into one report.
constexpr int kRefreshDelayMs = 100;

} // namespace

SceneStatisticsDialog::SceneStatisticsDialog(std::shared_ptr<const render::ShownContent> content, QWidget* parent)
    : QDialog(parent), m_content(std::move(content)), m_refresh(new QTimer(this))
{
    setObjectName(QStringLiteral("sceneStatisticsDialog"));
    setWindowTitle(tr("Mesh Statistics"));
    auto* layout = new QVBoxLayout(this);
    m_text = new QTextEdit(this);
    m_text->setObjectName(QStringLiteral("sceneStatisticsText"));
    m_text->setReadOnly(true);
    m_text->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont)); // the report's columns line up
    layout->addWidget(m_text);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(620, 560);
    m_refresh->setSingleShot(true);
    m_refresh->setInterval(kRefreshDelayMs);
    connect(m_refresh, &QTimer::timeout, this, &SceneStatisticsDialog::refresh);
    m_follow = m_content->subscribe([this](render::ShownLayer layer) {
        if ((layer == render::ShownLayer::Geometry || layer == render::ShownLayer::Pose) && isVisible())
            m_refresh->start();
    });
}

void SceneStatisticsDialog::showScene(const std::shared_ptr<const LoadedScene>& scene)
{
    m_scene = scene;
    m_refresh->stop();
    refresh();
}

void SceneStatisticsDialog::refresh()
{
    const std::shared_ptr<const Scene> shown = m_content->posedScene();
    if (!m_scene || !shown) {
        m_text->setPlainText(tr("Nothing is shown."));
        return;
    }
    m_text->setPlainText(shownSceneReport(*m_scene, *shown));
}

QString SceneStatisticsDialog::text() const
{
    return m_text->toPlainText();
}

QString shownSceneReport(const LoadedScene& loaded, const Scene& shown)
{
    QString text = SceneStatisticsDialog::tr("%1: %2 object(s)\n\n")
                       .arg(QString::fromStdString(loaded.displayName))
                       .arg(shown.objects.size());
    for (std::size_t i = 0; i < shown.objects.size(); ++i) {
        const SceneObject& object = shown.objects[i];
        const bool asFiled = i < loaded.reports.size() && i < loaded.scene.objects.size() &&
                             loaded.scene.objects[i].mesh.triangles == object.mesh.triangles &&
                             loaded.scene.objects[i].mesh.positions == object.mesh.positions;
        if (!asFiled)
            text += SceneStatisticsDialog::tr("As shown (the frame in the view, not the mesh as opened):\n");
        text +=
            QString::fromStdString(formatReport(asFiled ? loaded.reports[i] : validateMesh(object.mesh), object.name)) +
            QStringLiteral("\n");
    }
    return text;
}

} // namespace trimlab::ui
