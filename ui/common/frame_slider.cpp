#include "ui/common/frame_slider.h"

#include <QKeyEvent>
#include <QProxyStyle>

namespace trimlab::ui {

namespace {

// The style's answer to "which buttons set the value where they press": the left one.
// Qt then moves the handle to the click and starts a drag, as it does for the middle
// button by default.
class JumpToClickStyle : public QProxyStyle {
public:
    int styleHint(StyleHint hint, const QStyleOption* option, const QWidget* widget,
                  QStyleHintReturn* returnData) const override
    {
        if (hint == QStyle::SH_Slider_AbsoluteSetButtons)
            return int(Qt::LeftButton | Qt::MiddleButton);
        return QProxyStyle::styleHint(hint, option, widget, returnData);
    }
};

} // namespace

FrameSlider::FrameSlider(QWidget* parent) : QSlider(Qt::Horizontal, parent)
{
    // A proxy of the application's style, owned by this slider (setStyle does not take
    // ownership; a proxy made without a base style follows the application's).
    auto* style = new JumpToClickStyle;
    style->setParent(this);
    setStyle(style);
}

QString FrameSlider::inputHelp()
{
    return tr("click or drag: go there; ←/→ one step, PgUp/PgDn ten, Home/End first/last, Space play/pause");
}

void FrameSlider::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Space && event->modifiers() == Qt::NoModifier) {
        emit playToggleRequested();
        event->accept();
        return;
    }
    QSlider::keyPressEvent(event);
}

} // namespace trimlab::ui
