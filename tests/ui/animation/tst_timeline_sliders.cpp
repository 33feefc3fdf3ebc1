// The two timelines' sliders as a user drives them, without the main window: a click on
// the groove goes to the frame under the cursor (not one page towards it, which on a
// short deformation history landed on frame 0), and Space on the slider plays and
// pauses.
#include "tst_timeline_fixtures.h"

#include "ui/animation/timeline_panel.h"
#include "ui/common/frame_slider.h"
#include "ui/design/deformation_timeline_panel.h"

#include "widget_test_main.h"

#include <QSignalSpy>
#include <QSlider>
#include <QtTest>

#include <cmath>

using namespace trimlab;
using namespace trimlab::ui;

namespace {

/// The point on `slider`'s groove at `fraction` of its width, halfway down.
QPoint grooveAt(const QSlider& slider, double fraction)
{
    return {int(std::lround(fraction * (slider.width() - 1))), slider.height() / 2};
}

/// Shows `panel` at a fixed width and waits until it is on screen (clicks need that).
bool shown(QWidget& panel)
{
    panel.resize(800, panel.sizeHint().height());
    panel.show();
    return QTest::qWaitForWindowExposed(&panel);
}

/// Space on `slider` (the focus on it, as after a click) plays `panel`, Space again
/// pauses it.
template <class Panel>
bool spacePlaysAndPauses(Panel& panel, QSlider& slider)
{
    QTest::keyClick(&slider, Qt::Key_Space);
    const bool played = panel.isPlaying();
    QTest::keyClick(&slider, Qt::Key_Space);
    return played && !panel.isPlaying();
}

timeline::Timeline historyOfFrames(int frames)
{
    timeline::Timeline history(test::gridMesh());
    while (history.frameCount() < frames)
        history.appendFrame(test::frameTo(history, {}, {}));
    return history;
}

} // namespace

class TestTimelineSliders : public QObject {
    Q_OBJECT
private slots:
    void poseSliderGoesToTheClickedPose();
    void spaceOnThePoseSliderPlaysAndPauses();
    void deformationSliderGoesToTheClickedFrame();
    void spaceOnTheDeformationSliderPlaysAndPauses();
};

void TestTimelineSliders::poseSliderGoesToTheClickedPose()
{
    TimelinePanel panel;
    QStringList names;
    for (int i = 0; i < 101; ++i)
        names << QStringLiteral("pose %1").arg(i);
    panel.setPoses(names);
    QVERIFY(shown(panel));
    auto* slider = panel.findChild<QSlider*>(QStringLiteral("poseSlider"));
    QVERIFY(slider);
    QTest::mouseClick(slider, Qt::LeftButton, {}, grooveAt(*slider, 0.75));
    QVERIFY2(std::abs(panel.pose() - 75) <= 3, qPrintable(QString::number(panel.pose())));
    QTest::mouseClick(slider, Qt::LeftButton, {}, grooveAt(*slider, 0.2));
    QVERIFY2(std::abs(panel.pose() - 20) <= 3, qPrintable(QString::number(panel.pose())));
}

void TestTimelineSliders::spaceOnThePoseSliderPlaysAndPauses()
{
    TimelinePanel panel;
    panel.setPoses({QStringLiteral("a"), QStringLiteral("b"), QStringLiteral("c")});
    QVERIFY(shown(panel));
    auto* slider = panel.findChild<QSlider*>(QStringLiteral("poseSlider"));
    QVERIFY(slider);
    QSignalSpy playing(&panel, &TimelinePanel::playingChanged);
    QVERIFY(spacePlaysAndPauses(panel, *slider));
    QCOMPARE(playing.count(), 2);
    QVERIFY(slider->toolTip().contains(QStringLiteral("Space")));
}

// From the last of 8 frames, a click at 40 % of the groove chooses frame 3 or so; a page
// step towards it (QSlider's default) would have chosen frame 0.
void TestTimelineSliders::deformationSliderGoesToTheClickedFrame()
{
    const timeline::Timeline history = historyOfFrames(8);
    DeformationTimelinePanel panel;
    panel.setHistory(&history, 7);
    QVERIFY(shown(panel));
    auto* slider = panel.findChild<QSlider*>(QStringLiteral("deformationSlider"));
    QVERIFY(slider);
    QSignalSpy chosen(&panel, &DeformationTimelinePanel::frameChosen);
    QTest::mouseClick(slider, Qt::LeftButton, {}, grooveAt(*slider, 0.4));
    QVERIFY(!chosen.isEmpty());
    const int frame = chosen.last().at(0).toInt();
    QVERIFY2(frame >= 2 && frame <= 4, qPrintable(QString::number(frame)));
    QCOMPARE(panel.shownFrame(), frame);
}

void TestTimelineSliders::spaceOnTheDeformationSliderPlaysAndPauses()
{
    const timeline::Timeline history = historyOfFrames(4);
    DeformationTimelinePanel panel;
    panel.setHistory(&history, 0);
    QVERIFY(shown(panel));
    auto* slider = panel.findChild<QSlider*>(QStringLiteral("deformationSlider"));
    QVERIFY(slider);
    QVERIFY(spacePlaysAndPauses(panel, *slider));
}

TRIMLAB_WIDGET_TEST_MAIN(TestTimelineSliders)
#include "tst_timeline_sliders.moc"
