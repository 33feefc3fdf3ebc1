// The designer's core pieces without a window: the brush's pick and drag geometry in a
// known view, a brush drag and the frame it records, the control-point preview, the
// dynamic chain of a history's frame, and the check for vertices trimmed off.
#include "core/design/brush_drag.h"
#include "core/design/control_preview.h"
#include "core/design/session_chain.h"
#include "core/design/trimmed_region_check.h"

#include "core/deform/brush_topology.h"
#include "core/scene/shape_generators.h"
#include "core/surface/editable_surface.h"
#include "core/surface/subdivision_cages.h"
#include "core/timeline/control_edit.h"
#include "core/trim/dynamic_chain.h"

#include "tests/core/timeline/tst_timeline_fixtures.h"

#include <QtTest>

#include <cstring>

using namespace trimlab;

namespace {

// Looking down −z at the origin from z = 5 with a 90° field of view on 100×100 pixels:
// at depth 5 the view spans [−5, 5]², one pixel is 0.1 wide.
DragView topView()
{
    DragView view;
    view.camera.eye = {0.0, 0.0, 5.0};
    view.camera.target = {0.0, 0.0, 0.0};
    view.camera.fovyDegrees = 90.0;
    view.pixelSize = {100, 100};
    return view;
}

bool near(const glm::dvec3& a, const glm::dvec3& b, double tolerance = 1e-12)
{
    return glm::length(a - b) < tolerance;
}

bool sameBits(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec3)) == 0;
}

} // namespace

class TestDesignParts : public QObject {
    Q_OBJECT

private slots:
    void viewPlanePointsFollowThePixel()
    {
        const DragView view = topView();
        QVERIFY(near(viewPlanePoint(view, {50, 50}, 5.0), {0, 0, 0}));
        QVERIFY(near(viewPlanePoint(view, {0, 0}, 5.0), {-5, 5, 0}));
        QVERIFY(near(viewPlanePoint(view, {100, 50}, 2.5), {2.5, 0, 2.5}));
    }

    void pickedTrianglesMapThroughTheDynamicScene()
    {
        TrimPixel empty;
        QVERIFY(!pickedTriangle(empty, nullptr));
        TrimPixel pixel;
        pixel.primitiveId = 2;
        pixel.objectId = 1;
        QCOMPARE(pickedTriangle(pixel, nullptr), std::optional<std::uint32_t>(2));
        DynamicFrameScene scene;
        scene.meshTriangle[1] = {7, 8, 9};
        QCOMPARE(pickedTriangle(pixel, &scene), std::optional<std::uint32_t>(9));
        pixel.primitiveId = 3;
        QVERIFY(!pickedTriangle(pixel, &scene));
        pixel.objectId = 5;
        QVERIFY(!pickedTriangle(pixel, &scene));
    }

    // A press snaps onto its triangle in object space; a drag follows the cursor in the
    // view plane, or moves along the normal by how far the cursor went up.
    void picksSnapAndDragsFollowTheCursor()
    {
        const DragView view = topView();
        const TriangleMesh grid = test::gridMesh(5); // z = 0 over [0, 1]²
        glm::dmat4 model(1.0);
        model[3] = glm::dvec4(-0.5, -0.5, 0.0, 1.0); // the grid centred on the origin
        // Triangle 20 is (12, 13, 18): its corner 12 is the grid's centre (0.5, 0.5).
        const BrushPick pick = pickAnchor(view, {50, 50}, 20, 5.001, grid.positions, grid.triangles, model);
        QCOMPARE(pick.triangle, std::uint32_t(20));
        QCOMPARE(pick.viewDepth, 5.001);
        QVERIFY(near(pick.anchor, {0.5, 0.5, 0.0})); // snapped onto the plane from depth 5.001
        const BrushPick off = pickAnchor(view, {50, 50}, 0, 5.0, grid.positions, grid.triangles, model);
        QVERIFY(near(off.anchor, {0.25, 0.25, 0.0})); // the point of triangle 0 nearest the centre

        const BrushPick centre{0, {0.5, 0.5, 0.0}, 5.0, {50, 50}};
        QVERIFY(near(dragVector(view, centre, {60, 50}, false, {0, 0, 1}, model), {1, 0, 0}));
        QVERIFY(near(dragVector(view, centre, {50, 40}, true, {0, 0, 1}, model), {0, 0, 1}));
        QVERIFY(near(dragVector(view, centre, {50, 70}, true, {0, 0, 1}, model), {0, 0, -2}));
        glm::dmat4 scaled = model;
        scaled[0][0] = scaled[1][1] = scaled[2][2] = 2.0;
        QVERIFY(near(dragVector(view, centre, {60, 50}, false, {0, 0, 1}, scaled), {0.5, 0, 0}));
    }

    // A drag moves the grid's middle up; the frame holds exactly the vertices whose bits
    // changed, with their positions at the press and now. A click records nothing.
    void brushDragsRecordTheMovedVertices()
    {
        const DragView view = topView();
        const TriangleMesh grid = test::gridMesh(9);
        const deform::BrushTopology topology(grid);
        const glm::dmat4 model(1.0);
        std::uint32_t middle = 0;
        for (std::uint32_t t = 0; t < grid.triangles.size(); ++t)
            if (grid.triangles[t].x == 4 * 9 + 4)
                middle = t;
        const BrushPick pick = pickAnchor(view, {55, 45}, middle, 5.0, grid.positions, grid.triangles, model);
        deform::BrushSettings brush;
        brush.radius = 0.3;
        BrushDrag drag(topology, grid.positions, view, pick, brush, model);
        QVERIFY(!drag.moved());
        QVERIFY(drag.frame().vertices.empty());

        const std::vector<glm::vec3>& moved = drag.moveTo({55, 40}, true); // 5 px up: 0.5 out
        QVERIFY(drag.moved());
        QVERIFY(moved[4 * 9 + 4].z > 0.1f);
        QCOMPARE(moved[0], grid.positions[0]); // outside the radius
        const timeline::Frame frame = drag.frame();
        QVERIFY(!frame.vertices.empty());
        QVERIFY(std::is_sorted(frame.vertices.begin(), frame.vertices.end()));
        for (std::size_t i = 0; i < frame.vertices.size(); ++i) {
            QCOMPARE(frame.before[i], grid.positions[frame.vertices[i]]);
            QCOMPARE(frame.after[i], moved[frame.vertices[i]]);
        }
        QCOMPARE(frame.stroke.anchorTriangle, std::optional<std::uint32_t>(middle));
    }

    // Moving point 0 then only point 1: point 0 is back at its start and the mesh shows
    // the surface with point 1 moved alone, bit for bit.
    void controlPreviewPutsEarlierPointsBack()
    {
        EditableSurface surface(subdivisionDefinition(cubeCage(1.0), SubdivisionSettings{1, SubdivisionMode::Uniform}));
        const std::vector<glm::vec3> rest = surface.mesh().positions;
        const std::vector<glm::dvec3> start = surface.controlPoints();
        ControlPreview preview(surface, rest);
        QCOMPARE(preview.startControlPoints(), start);

        const std::vector<ControlPointTarget> first = {{0, start[0] + glm::dvec3(0.5, 0, 0)},
                                                       {0, start[0] + glm::dvec3(0, 0.5, 0)}}; // the last wins
        const std::vector<glm::vec3>& once = preview.update(first);
        QVERIFY(!sameBits(once, rest));
        QCOMPARE(surface.controlPoints()[0], start[0] + glm::dvec3(0, 0.5, 0));

        const std::vector<glm::vec3> shown = preview.update(std::vector<ControlPointTarget>{{1, start[1] * 1.5}});
        QCOMPARE(surface.controlPoints()[0], start[0]);
        EditableSurface alone(subdivisionDefinition(cubeCage(1.0), SubdivisionSettings{1, SubdivisionMode::Uniform}));
        const std::uint32_t index = 1;
        const glm::dvec3 target = start[1] * 1.5;
        (void)alone.moveControlPoints(std::span(&index, 1), std::span(&target, 1));
        QVERIFY(sameBits(shown, alone.mesh().positions));
        QVERIFY(sameBits(preview.positions(), shown));
    }

    // The chain of a two-set history: one level per set, the current set's rule last, the
    // shown frame's positions in the last level; a drag replaces only that level.
    void sessionChainsFollowTheHistory()
    {
        const timeline::Timeline history = test::exportTimeline();
        const int last = history.frameCount() - 1;
        glm::dmat4 model(1.0);
        model[3] = glm::dvec4(0.0, 0.0, 1.0, 1.0);
        const DynamicChain chain = dynamicChainTo(history, last, StaticRule::Parity, model);
        const std::vector<timeline::Timeline::ChainLink> links = history.chainTo(last);
        QCOMPARE(chain.levels.size(), links.size());
        QCOMPARE(chain.baseRule, StaticRule::Parity);
        for (std::size_t k = 0; k < links.size(); ++k)
            QCOMPARE(chain.levels[k].rule, links[k].rule);

        const std::vector<glm::vec3> reference = history.positionsAt(links.back().referenceFrame);
        const DynamicChainLevel same =
            dynamicShownLevel(history, reference, history.positionsAt(last), links.back().rule, model);
        QCOMPARE(same.rule, chain.levels.back().rule);
        QCOMPARE(same.frame.meshTriangle, chain.levels.back().frame.meshTriangle);
        QCOMPARE(same.frame.movedTriangles, chain.levels.back().frame.movedTriangles);
        QCOMPARE(same.frame.scene.objects[0].modelMatrix, model);

        std::vector<glm::vec3> dragged = history.positionsAt(last);
        dragged[21].z += 0.25f;
        const DynamicChainLevel live = dynamicShownLevel(history, reference, dragged, links.back().rule, model);
        QVERIFY(live.frame.movedTriangles > same.frame.movedTriangles);
    }

    void trimmedRegionSamplesStartWithTheAnchor()
    {
        std::vector<std::uint32_t> region(1000);
        for (std::uint32_t i = 0; i < region.size(); ++i)
            region[i] = 2 * i;
        const std::vector<std::uint32_t> samples = TrimmedRegionCheck::sample(region, {5, 7, 9});
        QVERIFY(samples.size() <= TrimmedRegionCheck::kMaxSamples);
        QVERIFY(samples.size() > TrimmedRegionCheck::kMaxSamples - 8);
        QVERIFY(std::is_sorted(samples.begin(), samples.end()));
        for (const std::uint32_t corner : {5u, 7u, 9u})
            QVERIFY(std::binary_search(samples.begin(), samples.end(), corner));
        QVERIFY(samples.back() > 1500); // spread over the whole region
        const std::vector<std::uint32_t> few =
            TrimmedRegionCheck::sample(std::vector<std::uint32_t>{1, 2, 5}, {2, 3, 4});
        QCOMPARE(few, (std::vector<std::uint32_t>{1, 2, 3, 4, 5}));
    }

    // Two nested spheres in one mesh: under the positive index rule the inner sphere lies
    // inside the solid (trimmed off); under parity it bounds the solid (on the trim).
    void innerSheetsAreTrimmedOffUnderThePositiveRule()
    {
        TriangleMesh mesh = makeIcosphere({0, 0, 0}, 1.0, 2);
        const std::size_t outer = mesh.vertexCount();
        appendMesh(mesh, makeIcosphere({0, 0, 0}, 0.5, 2));
        const deform::BrushTopology topology(mesh);
        const std::vector<std::uint32_t> inner = {std::uint32_t(outer), std::uint32_t(outer + 5)};
        const std::vector<std::uint32_t> shell = {0, 5};
        const glm::dmat4 model(1.0);
        const auto check = [&](StaticRule rule) {
            return TrimmedRegionCheck(
                makeDynamicChain(mesh.triangles, {mesh.positions, mesh.positions}, {DynamicRule::Confluent}, rule),
                model);
        };
        const TrimmedRegionCheck positive = check(StaticRule::PositiveIndex);
        QCOMPARE(positive.trimmedOff(topology, mesh.positions, inner, 1e-3), inner);
        QVERIFY(positive.trimmedOff(topology, mesh.positions, shell, 1e-3).empty());
        QVERIFY(check(StaticRule::Parity).trimmedOff(topology, mesh.positions, inner, 1e-3).empty());
    }
};

QTEST_APPLESS_MAIN(TestDesignParts)
#include "tst_design_parts.moc"
