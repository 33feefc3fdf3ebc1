#include "ui/window/scene_statistics.h"

#include <QDialogButtonBox>
#include <QFontDatabase>
#include <QTextEdit>
#include <QVBoxLayout>

namespace trimlab::ui {

SceneStatisticsDialog::SceneStatisticsDialog(QWidget* parent) : QDialog(parent)
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
}

void SceneStatisticsDialog::showScene(const std::shared_ptr<const LoadedScene>& scene)
{
    if (!scene) {
        m_text->setPlainText(tr("Nothing is shown."));
        return;
    }
    QString text = tr("%1: %2 object(s)\n\n").arg(QString::fromStdString(scene->displayName)).arg(scene->scene.objects.size());
    for (std::size_t i = 0; i < scene->reports.size() && i < scene->scene.objects.size(); ++i)
        text += QString::fromStdString(formatReport(scene->reports[i], scene->scene.objects[i].name)) +
                QStringLiteral("\n");
    m_text->setPlainText(text);
}

QString SceneStatisticsDialog::text() const
{
    return m_text->toPlainText();
}

} // namespace trimlab::ui
