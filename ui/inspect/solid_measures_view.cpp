#include "ui/inspect/solid_measures_view.h"

#include "ui/common/background_job.h"
#include "ui/common/rule_labels.h"

#include <QCheckBox>
#include <QLabel>
#include <QSettings>
#include <QTimer>
#include <QVBoxLayout>

namespace trimlab::ui {

namespace {

const QString kEnabledKey = QStringLiteral("scene/measureSolid");

/// How long the view must rest before its solid is trimmed again: a pause in a stroke
/// or between typed characters, not a frame of playback.
constexpr int kRestMs = 400;

} // namespace

QString measureNumber(double value)
{
    return QString::number(value, 'g', 6);
}

QString solidMeasuresLine(const SolidMeasures& measures, const TrimSettings& settings)
{
    return SolidMeasuresView::tr("Trimmed solid under %1 (exact): volume %2, surface area %3 (scene units)")
        .arg(classificationLabel(settings), measureNumber(measures.volume), measureNumber(measures.area));
}

SolidMeasuresView::SolidMeasuresView(SolidExport::ShownSource shown, QSettings& settings, QWidget* parent)
    : QGroupBox(tr("Trimmed solid"), parent),
      m_shown(std::move(shown)),
      m_settings(settings),
      m_rest(new QTimer(this)),
      m_job(newJob())
{
    setObjectName(QStringLiteral("solidMeasuresView"));
    auto* layout = new QVBoxLayout(this);
    m_enabled = new QCheckBox(tr("Measure as the view changes"), this);
    m_enabled->setObjectName(QStringLiteral("measureSolidCheck"));
    m_enabled->setToolTip(tr("Trim the solid shown exactly in the background whenever the view rests, and show its "
                             "volume and surface area. Turn off for meshes too large to trim often."));
    m_enabled->setChecked(m_settings.value(kEnabledKey, true).toBool());
    layout->addWidget(m_enabled);
    m_text = new QLabel(this);
    m_text->setObjectName(QStringLiteral("solidMeasuresLabel"));
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_text);
    m_rest->setSingleShot(true);
    m_rest->setInterval(kRestMs);
    connect(m_rest, &QTimer::timeout, this, [this] {
        const SolidExport::Shown now = m_shown();
        if (subjectOf(now) == m_subject)
            startJob(now);
        else
            follow(); // it changed again while resting
    });
    connect(m_enabled, &QCheckBox::toggled, this, &SolidMeasuresView::setMeasuresAsShown);
    setMeasuresAsShown(m_enabled->isChecked());
}

SolidMeasuresView::~SolidMeasuresView() = default;

SolidMeasuresView::Subject SolidMeasuresView::subjectOf(const SolidExport::Shown& shown)
{
    return Subject{shown.scene, shown.settings.trimEnabled, shown.settings.rule, shown.settings.csg, shown.refusal};
}

bool SolidMeasuresView::measuresAsShown() const
{
    return m_enabled->isChecked();
}

void SolidMeasuresView::setMeasuresAsShown(bool on)
{
    if (m_enabled->isChecked() != on) {
        m_enabled->setChecked(on); // comes back here through toggled()
        return;
    }
    m_settings.setValue(kEnabledKey, on);
    stopJob();
    m_subject.reset();
    if (!on) {
        m_text->setText(tr("Check to see the volume and surface area of the solid shown."));
        return;
    }
    m_text->setText(tr("Measured when the view shows a solid."));
    follow();
}

void SolidMeasuresView::showEvent(QShowEvent* event)
{
    QGroupBox::showEvent(event);
    QTimer::singleShot(0, this, &SolidMeasuresView::follow); // once the layout gave it its region
}

// Shown and not behind another tab of its dock (a tabbed dock's widgets stay visible).
bool SolidMeasuresView::onScreen() const
{
    return isVisible() && !visibleRegion().isEmpty();
}

void SolidMeasuresView::follow()
{
    if (!onScreen() || !m_enabled->isChecked())
        return;
    const SolidExport::Shown shown = m_shown();
    const Subject subject = subjectOf(shown);
    if (m_subject == subject)
        return;
    stopJob();
    m_subject = subject;
    if (!shown.scene || !shown.refusal.isEmpty()) {
        m_text->setText(tr("No solid: %1").arg(shown.refusal));
        emit measured();
        return;
    }
    m_text->setText(tr("Measuring…"));
    m_rest->start();
}

void SolidMeasuresView::startJob(const SolidExport::Shown& shown)
{
    TrimSettings settings = shown.settings;
    settings.setClipSet({}); // the whole solid: the sections are Mesh Statistics'
    m_measuredSettings = settings;
    const std::shared_ptr<const Scene> scene = shown.scene;
    m_job->start(
        [scene, settings](const TaskControl& control) { return measureTrimmedSolid(*scene, settings, control); });
}

BackgroundJob<SolidMeasures>* SolidMeasuresView::newJob()
{
    auto* job = new BackgroundJob<SolidMeasures>(this);
    connect(job, &BackgroundJobBase::succeeded, this, [this, job] {
        showResult(job->result());
        emit measured();
    });
    connect(job, &BackgroundJobBase::failed, this, [this](const QString& message) {
        m_text->setText(tr("The measurement failed: %1").arg(message));
        emit measured();
    });
    return job;
}

// The measurement under way measures what is no longer asked for: let it go.
void SolidMeasuresView::stopJob()
{
    m_rest->stop();
    if (!m_job->isRunning())
        return;
    m_job->abandon(this);
    m_job = newJob();
}

void SolidMeasuresView::showResult(const SolidMeasures& measures)
{
    m_text->setText(solidMeasuresLine(measures, m_measuredSettings));
}

bool SolidMeasuresView::isMeasuring() const
{
    return m_rest->isActive() || m_job->isRunning();
}

QString SolidMeasuresView::text() const
{
    return m_text->text();
}

} // namespace trimlab::ui
