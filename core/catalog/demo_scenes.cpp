#include "core/catalog/demo_scenes.h"

#include "core/catalog/demo_shapes.h"
#include "core/scene/shape_generators.h"

#include <array>

namespace trimlab {

namespace {

Scene singleObject(std::string name, TriangleMesh mesh)
{
    Scene scene;
    scene.objects.push_back({std::move(name), std::move(mesh), glm::dmat4(1.0)});
    return scene;
}

Scene pushedSphereScene()
{
    return singleObject("pushed-sphere", makePushedSphere());
}

Scene crossingLoopScene()
{
    return singleObject("crossing-loop", makeCrossingLoop());
}

Scene nestedSpheresScene()
{
    Scene scene;
    scene.objects.push_back({"outer", makeIcosphere(glm::dvec3(0.0), 1.0, 4), glm::dmat4(1.0)});
    scene.objects.push_back({"inner", makeIcosphere(glm::dvec3(0.0), 0.5, 3), glm::dmat4(1.0)});
    return scene;
}

Scene sphereScene()
{
    return singleObject("sphere", makeIcosphere(glm::dvec3(0.0), 1.0, 4));
}

// Three overlapping solids for CSG, capping and collisions (objects 0, 1, 2): the
// self-crossing pushed sphere, a ball through its side and a ring around its equator.
Scene csgTrioScene()
{
    Scene scene;
    scene.objects.push_back({"pushed sphere", makePushedSphere(64, 32), glm::dmat4(1.0)});
    scene.objects.push_back({"ball", makeIcosphere(glm::dvec3(0.8, 0.3, 0.4), 0.7, 3), glm::dmat4(1.0)});
    scene.objects.push_back({"ring", makeTorus(glm::dvec3(-0.15, 0.1, 0.0), 1.0, 0.28, 48, 24), glm::dmat4(1.0)});
    return scene;
}

struct DemoEntry {
    std::string_view name;
    std::string_view description;
    Scene (*make)();
};

constexpr std::array<DemoEntry, 5> kDemos = {{
    {"pushed-sphere",
     "A sphere with a finger pushed through its south cap: the alternating border rule trims "
     "a hole through it (genus 0 to 1).",
     pushedSphereScene},
    {"crossing-loop",
     "A tube swept along a figure-eight that passes through itself: an immersed torus with "
     "winding index 2 at the crossing.",
     crossingLoopScene},
    {"nested-spheres",
     "An outer unit sphere containing a sphere of radius 0.5, both outward (winding index 2 "
     "inside the inner one).",
     nestedSpheresScene},
    {"sphere", "A unit icosphere (5120 triangles): the simplest closed surface.", sphereScene},
    {"csg-trio",
     "Three overlapping solids for CSG and capping: the self-crossing pushed sphere (object 0), a ball "
     "(1) and a ring (2), e.g. --csg \"0 | 1 - 2\".",
     csgTrioScene},
}};

const DemoEntry* findDemo(std::string_view name)
{
    for (const DemoEntry& entry : kDemos) {
        if (entry.name == name)
            return &entry;
    }
    return nullptr;
}

} // namespace

std::vector<std::string> demoSceneNames()
{
    std::vector<std::string> names;
    for (const DemoEntry& entry : kDemos)
        names.emplace_back(entry.name);
    return names;
}

std::string_view demoSceneDescription(std::string_view name)
{
    const DemoEntry* entry = findDemo(name);
    return entry ? entry->description : std::string_view();
}

std::optional<Scene> makeDemoScene(std::string_view name)
{
    const DemoEntry* entry = findDemo(name);
    if (!entry)
        return std::nullopt;
    return entry->make();
}

} // namespace trimlab
