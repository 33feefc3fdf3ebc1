// The control-point tool's picking and selection rules (core/design/control_point_pick.h).
#include "core/design/control_point_pick.h"

#include <QtTest>

using namespace trimlab;

class TestControlPointPick : public QObject {
    Q_OBJECT
private slots:
    void nearestPointWithinRadius();
    void clickRules();
};

void TestControlPointPick::nearestPointWithinRadius()
{
    const std::vector<std::optional<glm::dvec2>> points{glm::dvec2(10, 10), std::nullopt, glm::dvec2(14, 10),
                                                        glm::dvec2(100, 100), glm::dvec2(14, 10)};
    QCOMPARE(nearestPoint(glm::dvec2(11, 10), points, 8.0), std::optional<std::uint32_t>(0));
    QCOMPARE(nearestPoint(glm::dvec2(13, 10), points, 8.0), std::optional<std::uint32_t>(2)); // tie with 4: lower
    QCOMPARE(nearestPoint(glm::dvec2(50, 50), points, 8.0), std::optional<std::uint32_t>());
    QCOMPARE(nearestPoint(glm::dvec2(100, 108), points, 8.0), std::optional<std::uint32_t>(3)); // on the radius
    QCOMPARE(nearestPoint(glm::dvec2(100, 108.01), points, 8.0), std::optional<std::uint32_t>());
}

void TestControlPointPick::clickRules()
{
    using Selection = std::vector<std::uint32_t>;
    QCOMPARE(clickedSelection({1, 5}, 3u, false), Selection{3});
    QCOMPARE(clickedSelection({1, 5}, std::nullopt, false), Selection{});
    QCOMPARE(clickedSelection({1, 5}, 3u, true), (Selection{1, 3, 5}));
    QCOMPARE(clickedSelection({1, 3, 5}, 3u, true), (Selection{1, 5}));
    QCOMPARE(clickedSelection({1, 5}, std::nullopt, true), (Selection{1, 5}));
}

QTEST_APPLESS_MAIN(TestControlPointPick)
#include "tst_control_point_pick.moc"
