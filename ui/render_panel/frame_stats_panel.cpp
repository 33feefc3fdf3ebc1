#include "ui/render_panel/frame_stats_panel.h"

#include "ui/render_panel/method_group.h"
#include "ui/viewport/viewport_widget.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

namespace trimlab::ui {

namespace {

const QString kDash = QStringLiteral("–");
const QString kAlarmStyle = QStringLiteral("QLabel { background: #c0392b; color: white; padding: 4px; }");
const QString kAlarmValueStyle = QStringLiteral("QLabel { color: #c0392b; font-weight: bold; }");

QString countText(std::uint64_t count)
{
    return QLocale().toString(qulonglong(count));
}

// The GPU's time and, beside it, the CPU's for issuing the frame: with pipelined frames the
// two overlap, so the frame rate follows the larger.
QString frameTimeText(const render::FrameStats& stats)
{
    const QString cpu = FrameStatsPanel::tr("CPU %1 ms").arg(stats.issueMilliseconds, 0, 'f', 2);
    if (stats.gpuMilliseconds >= 0.0)
        return FrameStatsPanel::tr("%1 ms (GPU) · %2").arg(stats.gpuMilliseconds, 0, 'f', 2).arg(cpu);
    return FrameStatsPanel::tr("%1 ms (wall) · %2").arg(stats.wallMilliseconds, 0, 'f', 2).arg(cpu);
}

QString lockText(const render::FrameStats& stats)
{
    QString text = FrameStatsPanel::tr(render::lockDescription(stats.methodStats));
    if (stats.counts.spinGiveUps > 0)
        text += FrameStatsPanel::tr(", %1 fragments gave up").arg(countText(stats.counts.spinGiveUps));
    return text;
}

} // namespace

FrameStatsPanel::FrameStatsPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("frameStatsPanel"));
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    layout->addLayout(form);
    m_method = addRow(form, tr("Method"), "statsMethodLabel", tr("The multi-fragment method of the last frame"));
    m_frameTime = addRow(form, tr("Time per frame"), "statsFrameTimeLabel",
                         tr("GPU time of the last frame (wall-clock time when the driver's timer is unusable), and the "
                            "CPU's time to issue it; the GPU draws one frame while the CPU prepares the next"));
    m_passes = addRow(form, tr("Geometry passes"), "statsGeometryPassesLabel",
                      tr("Times the scene was rasterised (and full-screen passes)"));
    m_memory =
        addRow(form, tr("GPU memory"), "statsMemoryLabel", tr("Method storage, render target and scene buffers"));
    m_fragments = addRow(form, tr("Fragments in span"), "statsFragmentsLabel",
                         tr("Fragments inside the kept span (after clipping)"));
    m_stored =
        addRow(form, tr("Fragments stored"), "statsStoredLabel", tr("Fragments written to the method's storage"));
    m_lost = addRow(form, tr("Fragments lost"), "statsLostLabel",
                    tr("Fragments not stored: beyond the capacity, or given up on the spin-lock"));
    m_overflow = addRow(form, tr("Overflowed pixels"), "statsOverflowLabel", tr("Pixels that lost fragments"));
    m_unresolved = addRow(form, tr("Unresolved pixels"), "statsUnresolvedLabel",
                          tr("Overflowed pixels whose trim point may have been lost; they show magenta"));
    m_lock = addRow(form, tr("Lock"), "statsLockLabel",
                    tr("How the store pass serialises a pixel's fragments: fragment shader interlock where the "
                       "driver has it, else a bounded spin-lock (peeling methods need neither)"));
    layout->addWidget(createAdviceBox());
    clear();
}

QLabel* FrameStatsPanel::addRow(QFormLayout* form, const QString& label, const char* objectName, const QString& toolTip)
{
    auto* value = new QLabel(this);
    value->setObjectName(QString::fromLatin1(objectName));
    value->setToolTip(toolTip);
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(label, value);
    return value;
}

QWidget* FrameStatsPanel::createAdviceBox()
{
    m_adviceBox = new QWidget(this);
    m_adviceBox->setObjectName(QStringLiteral("overflowAdvice"));
    auto* layout = new QVBoxLayout(m_adviceBox);
    layout->setContentsMargins(0, 0, 0, 0);
    m_warning = new QLabel(m_adviceBox);
    m_warning->setObjectName(QStringLiteral("overflowWarningLabel"));
    m_warning->setWordWrap(true);
    m_warning->setStyleSheet(kAlarmStyle);
    layout->addWidget(m_warning);
    auto* buttons = new QHBoxLayout;
    m_switch = new QToolButton(m_adviceBox);
    m_switch->setObjectName(QStringLiteral("switchMethodButton"));
    m_switch->setPopupMode(QToolButton::MenuButtonPopup);
    m_switch->setMenu(new QMenu(m_switch));
    m_raiseK = new QPushButton(m_adviceBox);
    m_raiseK->setObjectName(QStringLiteral("raiseKButton"));
    buttons->addWidget(m_switch);
    buttons->addWidget(m_raiseK);
    buttons->addStretch();
    layout->addLayout(buttons);
    connect(m_switch, &QToolButton::clicked, this, [this] {
        if (!m_advice.unboundedMethods.empty())
            emit methodRequested(m_advice.unboundedMethods.front());
    });
    connect(m_raiseK, &QPushButton::clicked, this, [this] {
        if (m_advice.raiseKTo)
            emit kRequested(*m_advice.raiseKTo);
    });
    return m_adviceBox;
}

void FrameStatsPanel::showFrame(const render::ViewFrame& frame)
{
    const render::FrameStats& s = frame.stats;
    m_method->setText(methodDisplayName(render::methodInfo(s.method)));
    m_frameTime->setText(frameTimeText(s));
    m_passes->setText(
        tr("%1 (+ %2 full-screen)").arg(s.methodStats.geometryPasses).arg(s.methodStats.fullscreenPasses));
    m_memory->setText(tr("%1 MB").arg(s.bufferMegabytes, 0, 'f', 1));
    m_fragments->setText(countText(s.counts.fragmentsInSpan));
    m_stored->setText(countText(s.counts.fragmentsStored));
    m_lost->setText(countText(s.counts.fragmentsLost));
    m_overflow->setText(countText(s.counts.overflowPixels));
    m_unresolved->setText(countText(s.counts.unresolvedPixels));
    m_lock->setText(lockText(s));
    showAdvice(adviseOnOverflow(s.method, s.counts, frame.parameters, frame.largestPixelCount));
}

void FrameStatsPanel::clear()
{
    for (QLabel* label :
         {m_method, m_frameTime, m_passes, m_memory, m_fragments, m_stored, m_lost, m_overflow, m_unresolved, m_lock})
        label->setText(kDash);
    showAdvice({});
}

void FrameStatsPanel::showAdvice(const OverflowAdvice& advice)
{
    m_advice = advice;
    m_adviceBox->setVisible(advice.overflowing);
    m_lost->setStyleSheet(advice.overflowing ? kAlarmValueStyle : QString());
    m_unresolved->setStyleSheet(advice.overflowing ? kAlarmValueStyle : QString());
    if (!advice.overflowing)
        return;
    m_warning->setText(advice.message);
    m_switch->menu()->clear();
    for (const render::FragmentMethodKind kind : advice.unboundedMethods) {
        const render::MethodInfo& info = render::methodInfo(kind);
        QAction* action = m_switch->menu()->addAction(tr("Switch to %1").arg(methodDisplayName(info)));
        action->setToolTip(methodToolTip(info));
        connect(action, &QAction::triggered, this, [this, kind] { emit methodRequested(kind); });
    }
    m_switch->setVisible(!advice.unboundedMethods.empty());
    if (!advice.unboundedMethods.empty())
        m_switch->setText(
            tr("Switch to %1").arg(methodDisplayName(render::methodInfo(advice.unboundedMethods.front()))));
    m_raiseK->setVisible(advice.raiseKTo.has_value());
    if (advice.raiseKTo) {
        m_raiseK->setText(tr("Raise k to %1").arg(*advice.raiseKTo));
        m_raiseK->setToolTip(advice.raiseKHoldsDeepestPixel
                                 ? tr("The deepest pixel of this frame has %1 fragments.").arg(*advice.raiseKTo)
                                 : tr("This method does not count beyond k: doubles k."));
    }
}

} // namespace trimlab::ui
