#pragma once
/// \file
/// The "Frame statistics" dock's upper part: what the last frame cost and found — method,
/// time per frame (GPU, or wall when the driver has no usable timer), geometry passes,
/// GPU memory, fragments in the span, stored and lost, overflowed and unresolved pixels,
/// and the critical-section mechanism (fragment shader interlock or spin-lock). When the
/// frame overflowed it says so in red and offers the remedies of overflow_advice.h:
/// "Switch to …" (an unbounded method; the arrow lists the others) and "Raise k to N".

#include "render/mfr/fragment_method.h"
#include "ui/render_panel/overflow_advice.h"

#include <QWidget>

class QFormLayout;
class QLabel;
class QPushButton;
class QToolButton;

namespace trimlab::render {
struct ViewFrame;
}

namespace trimlab::ui {

class FrameStatsPanel : public QWidget {
    Q_OBJECT
public:
    explicit FrameStatsPanel(QWidget* parent = nullptr);

    /// Shows `frame` (its statistics and, when it overflowed, the advice).
    void showFrame(const render::ViewFrame& frame);
    /// Dashes everywhere, no advice (no frame, or the view cannot render).
    void clear();

    [[nodiscard]] const OverflowAdvice& advice() const { return m_advice; }

signals:
    /// The user asked to switch to `method`.
    void methodRequested(trimlab::render::FragmentMethodKind method);
    /// The user asked for a larger k.
    void kRequested(int k);

private:
    QLabel* addRow(QFormLayout* form, const QString& label, const char* objectName, const QString& toolTip);
    QWidget* createAdviceBox();
    void showAdvice(const OverflowAdvice& advice);

    QLabel* m_method = nullptr;
    QLabel* m_frameTime = nullptr;
    QLabel* m_passes = nullptr;
    QLabel* m_memory = nullptr;
    QLabel* m_fragments = nullptr;
    QLabel* m_stored = nullptr;
    QLabel* m_lost = nullptr;
    QLabel* m_overflow = nullptr;
    QLabel* m_unresolved = nullptr;
    QLabel* m_lock = nullptr;
    QWidget* m_adviceBox = nullptr;
    QLabel* m_warning = nullptr;
    QToolButton* m_switch = nullptr;
    QPushButton* m_raiseK = nullptr;
    OverflowAdvice m_advice;
};

} // namespace trimlab::ui
