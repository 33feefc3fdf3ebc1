// Writes the seed inputs that tests/data cannot provide, into the folder given as the
// only argument: small valid .trimlab projects (project/), PFM images (pfm/) and skeleton
// files (skeleton_json/). Built in
// the fuzz tree; scripts/fuzz runs it before fuzzing.
#include "core/io/pfm_image.h"
#include "core/skeleton/skeleton_json.h"
#include "core/surface/nurbs_json.h"
#include "core/surface/nurbs_primitives.h"
#include "core/timeline/project_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace {

using namespace trimlab;

TriangleMesh grid(int n)
{
    TriangleMesh mesh;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            mesh.positions.emplace_back(float(i) / float(n - 1), float(j) / float(n - 1), 0.0f);
    for (int j = 0; j + 1 < n; ++j) {
        for (int i = 0; i + 1 < n; ++i) {
            const auto v = std::uint32_t(j * n + i);
            const auto un = std::uint32_t(n);
            mesh.triangles.emplace_back(v, v + 1, v + un + 1);
            mesh.triangles.emplace_back(v, v + un + 1, v + un);
        }
    }
    return mesh;
}

timeline::Frame frameTo(const timeline::Timeline& t, std::vector<std::uint32_t> vertices, std::vector<glm::vec3> after)
{
    timeline::Frame frame;
    frame.vertices = std::move(vertices);
    for (const std::uint32_t v : frame.vertices)
        frame.before.push_back(t.currentPositions()[v]);
    frame.after = std::move(after);
    frame.stroke.anchor = {0.25, 0.5, 0.0};
    frame.stroke.anchorTriangle = 1;
    frame.stroke.drag = {0.0, 0.0, 0.1};
    return frame;
}

void writeText(const std::filesystem::path& path, const std::string& text)
{
    std::ofstream(path, std::ios::binary) << text;
}

} // namespace

namespace {

// Every primitive alone (closed, periodic, poles, open patch) and all of them in one file.
void writeNurbsSeeds(const std::filesystem::path& folder)
{
    std::filesystem::create_directories(folder);
    const std::vector<NurbsSurface> surfaces{
        makeNurbsSphere({0.0, 0.0, 0.0}, 1.0), makeNurbsTorus({0.0, 0.0, 0.0}, 1.0, 0.25),
        makeNurbsCylinder({0.0, 0.0, 0.0}, 0.5, 2.0), makeNurbsCappedTube({0.0, 0.0, 0.0}, 0.5, 1.0),
        makeNurbsPatch({0.0, 0.0, 0.0}, 2.0, 2.0, 5, 4)};
    for (std::size_t i = 0; i < surfaces.size(); ++i)
        writeText(folder / ("surface_" + std::to_string(i) + ".json"), nurbsJson(std::span(&surfaces[i], 1)));
    writeText(folder / "all.json", nurbsJson(surfaces));
}

// Cage seeds start with the scheme byte of fuzz_cage_obj ('0' Catmull–Clark, '1' Loop):
// a cube with a crease ring and a corner, and a tetrahedron.
void writeCageSeeds(const std::filesystem::path& folder)
{
    std::filesystem::create_directories(folder);
    writeText(folder / "creased_cube.obj", "0v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
                                           "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
                                           "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"
                                           "t crease 2/1/0 4 5 10\nt crease 2/1/0 5 6 2.5\nt corner 1/1/0 0 10\n");
    writeText(folder / "tetrahedron.obj", "1v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                          "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n");
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUTPUT_FOLDER\n", argv[0]);
        return 2;
    }
    const std::filesystem::path out = argv[1];
    std::filesystem::create_directories(out / "project");
    std::filesystem::create_directories(out / "pfm");
    std::filesystem::create_directories(out / "skeleton_json");

    timeline::Timeline empty(grid(2));
    writeText(out / "project" / "empty_history.trimlab", timeline::projectJson(empty));

    timeline::Timeline t(grid(3), DynamicRule::ConstructiveAdditive);
    t.appendFrame(frameTo(t, {1, 4}, {{0.5f, 0.0f, 0.25f}, {0.5f, 0.5f, -0.1f}}));
    t.startSet(DynamicRule::Confluent);
    t.appendFrame(frameTo(t, {4, 8}, {{0.5f, 0.5f, 0.3f}, {1.0f, 1.0f, 1e-7f}}));
    t.appendFrame(frameTo(t, {}, {}));
    timeline::ProjectExtras extras;
    extras.view = timeline::ProjectView{};
    extras.staticRule = StaticRule::AlternatingBorder;
    writeText(out / "project" / "two_sets.trimlab", timeline::projectJson(t, extras));

    io::FloatImage image{3, 2, {0.5f, 1.0f, 2.0f, -1.0f, 0.0f, std::numeric_limits<float>::infinity()}};
    io::writePfm(out / "pfm" / "depth_3x2.pfm", image);

    // A three-joint chain with its curve skeleton: every section of the format.
    SkeletonRig rig;
    rig.joints = {{0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 2.0, 0.5}};
    rig.parent = {-1, 0, 1};
    rig.root = 0;
    rig.bones = {{0, 1, -1}, {1, 2, 0}};
    rig.vertexJoint = {0, 1, 1, 2};
    CurveSkeleton curve;
    curve.nodes = {{0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 2.0, 0.5}};
    curve.edges = {{0, 1}, {1, 2}};
    curve.vertexNode = {0, 1, 1, 2};
    writeText(out / "skeleton_json" / "chain.json", skeletonJson(rig, &curve));
    writeText(out / "skeleton_json" / "chain_without_curve.json", skeletonJson(rig));

    writeNurbsSeeds(out / "nurbs_json");
    writeCageSeeds(out / "cage_obj");
    return 0;
}
