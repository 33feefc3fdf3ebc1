#include "ui/window/scene_statistics.h"

#include "ui/common/background_job.h"
#include "ui/inspect/solid_measures_view.h"

#include <QDialogButtonBox>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTextEdit>
#include <QTimer>
#include <QVBoxLayout>

namespace trimlab::ui {

namespace {

/// Milliseconds a burst of content changes is gathered into one report.
constexpr int kRefreshDelayMs = 100;

QString crossingsText(const SelfIntersections& crossings)
{
    if (crossings.pairs == 0)
        return SceneStatisticsDialog::tr("does not cross itself");
    const QString pairs = crossings.pairs == 1
                              ? SceneStatisticsDialog::tr("1 triangle pair crosses")
                              : SceneStatisticsDialog::tr("%1 triangle pairs cross").arg(crossings.pairs);
    return SceneStatisticsDialog::tr("%1 (%2 triangles involved)").arg(pairs).arg(crossings.triangles);
}

} // namespace

SceneMeasures measureShown(const SolidExport::Shown& shown, const TaskControl& control)
{
    SceneMeasures measures;
    measures.settings = shown.settings;
    if (shown.refusal.isEmpty())
        measures.solid = measureTrimmedSolid(*shown.scene, shown.settings, control);
    else
        measures.noSolid = shown.remedy.isEmpty() ? shown.refusal : shown.refusal + QLatin1Char(' ') + shown.remedy;
    if (shown.scene)
        for (const SceneObject& object : shown.scene->objects) {
            measures.objectNames.push_back(QString::fromStdString(object.name));
            measures.crossings.push_back(selfIntersections(object.mesh, control));
        }
    return measures;
}

QString sceneMeasuresText(const SceneMeasures& measures)
{
    QStringList lines;
    if (measures.solid) {
        const SolidMeasures& solid = *measures.solid;
        lines << solidMeasuresLine(solid, measures.settings);
        for (const PlaneSection& section : solid.sections)
            lines << SceneStatisticsDialog::tr("  cross-section in clipping plane %1: area %2")
                         .arg(section.plane + 1)
                         .arg(measureNumber(section.area));
    } else {
        lines << SceneStatisticsDialog::tr("No trimmed solid to measure: %1").arg(measures.noSolid);
    }
    for (std::size_t i = 0; i < measures.crossings.size(); ++i)
        lines << SceneStatisticsDialog::tr("Self-intersections of %1: %2")
                     .arg(measures.objectNames[i], crossingsText(measures.crossings[i]));
    return lines.join(QLatin1Char('\n'));
}

SceneStatisticsDialog::SceneStatisticsDialog(std::shared_ptr<const render::ShownContent> content,
                                             SolidExport::ShownSource shownSolid, QWidget* parent)
    : QDialog(parent),
      m_content(std::move(content)),
      m_refresh(new QTimer(this)),
      m_shownSolid(std::move(shownSolid)),
      m_job(new BackgroundJob<SceneMeasures>(this))
{
    setObjectName(QStringLiteral("sceneStatisticsDialog"));
    setWindowTitle(tr("Mesh Statistics"));
    auto* layout = new QVBoxLayout(this);
    m_text = new QTextEdit(this);
    m_text->setObjectName(QStringLiteral("sceneStatisticsText"));
    m_text->setReadOnly(true);
    m_text->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont)); // the report's columns line up
    layout->addWidget(m_text);
    auto* measureRow = new QHBoxLayout;
    m_measure = new QPushButton(tr("&Measure"), this);
    m_measure->setObjectName(QStringLiteral("measureSolidButton"));
    m_measure->setToolTip(tr("Measure the trimmed solid shown (exactly: its volume, surface area and the "
                             "cross-section in each clipping plane) and count where each object crosses itself"));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName(QStringLiteral("cancelMeasureButton"));
    m_cancel->setEnabled(false);
    measureRow->addWidget(m_measure);
    measureRow->addWidget(m_cancel);
    measureRow->addStretch(1);
    layout->addLayout(measureRow);
    m_measures = new QLabel(this);
    m_measures->setObjectName(QStringLiteral("solidMeasuresText"));
    m_measures->setWordWrap(true);
    m_measures->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_measures);
    connect(m_measure, &QPushButton::clicked, this, &SceneStatisticsDialog::measure);
    connect(m_cancel, &QPushButton::clicked, m_job, &BackgroundJobBase::cancel);
    connect(m_job, &BackgroundJobBase::succeeded, this,
            [this] { m_measures->setText(sceneMeasuresText(m_job->result())); });
    connect(m_job, &BackgroundJobBase::failed, this,
            [this](const QString& message) { m_measures->setText(tr("The measurement failed: %1").arg(message)); });
    connect(m_job, &BackgroundJobBase::canceled, this, [this] { m_measures->setText(tr("Measurement canceled.")); });
    connect(m_job, &BackgroundJobBase::finished, this, [this] {
        showMeasuring(false);
        emit measured();
    });
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(620, 560);
    m_refresh->setSingleShot(true);
    m_refresh->setInterval(kRefreshDelayMs);
    connect(m_refresh, &QTimer::timeout, this, &SceneStatisticsDialog::refresh);
    m_follow = m_content->subscribe([this](render::ShownLayer layer) {
        if (layer != render::ShownLayer::Geometry && layer != render::ShownLayer::Pose)
            return;
        forgetMeasures();
        if (isVisible())
            m_refresh->start();
    });
}

SceneStatisticsDialog::~SceneStatisticsDialog() = default;

void SceneStatisticsDialog::showScene(const std::shared_ptr<const LoadedScene>& scene)
{
    m_scene = scene;
    m_refresh->stop();
    forgetMeasures();
    refresh();
}

void SceneStatisticsDialog::measure()
{
    if (m_job->isRunning())
        return;
    const SolidExport::Shown shown = m_shownSolid();
    if (!shown.scene) {
        m_measures->setText(tr("Nothing is shown."));
        return;
    }
    showMeasuring(true);
    m_measures->setText(tr("Measuring…"));
    m_job->start([shown](const TaskControl& control) { return measureShown(shown, control); });
}

bool SceneStatisticsDialog::isMeasuring() const
{
    return m_job->isRunning();
}

QString SceneStatisticsDialog::measuresText() const
{
    return m_measures->text();
}

// What was measured belongs to a frame no longer shown.
void SceneStatisticsDialog::forgetMeasures()
{
    if (m_job->isRunning())
        m_job->cancel();
    m_measures->setText(tr("Measure computes the trimmed solid's volume, area and sections for the frame shown."));
}

void SceneStatisticsDialog::showMeasuring(bool running)
{
    m_measure->setEnabled(!running);
    m_cancel->setEnabled(running);
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
