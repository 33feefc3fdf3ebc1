#include "app/bench_scenes.h"

#include "core/mesh/loop_subdivision.h"
#include "core/mesh/mesh_validation.h"
#include "core/scene/object_transform.h"
#include "core/trim/csg_expression.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>

namespace trimlab::app {

namespace {

/// How a catalog scene is built.
enum class Kind { Demo, File, BunnyInCube, CsgOfThree };

struct CatalogEntry {
    const char* name;
    Kind kind;
    const char* source; ///< demo:NAME, or a path relative to the data folder
    StaticRule rule;
    bool clipHalf;       ///< keep z <= 0 (the GUI's first clipping plane)
    double keptFraction; ///< BunnyInCube: the part of the cube's height kept, from below
};

constexpr const char* kBunny = "static/odedstein-bunny.obj.gz";
constexpr const char* kBunnyHr = "static/odedstein-bunny_hr.obj.gz";
constexpr const char* kDragon = "selfintersect/quartet-dragon.obj.gz";
constexpr const char* kElephant = "anim/elephant-gallop/elephant-gallop-05.obj.gz";

constexpr std::array<CatalogEntry, 11> kCatalog = {{
    {"demo:pushed-sphere", Kind::Demo, "demo:pushed-sphere", StaticRule::AlternatingBorder, true, 1.0},
    {"demo:crossing-loop", Kind::Demo, "demo:crossing-loop", StaticRule::AlternatingBorder, false, 1.0},
    {"demo:nested-spheres", Kind::Demo, "demo:nested-spheres", StaticRule::Parity, true, 1.0},
    {"bunny-cube-25", Kind::BunnyInCube, kBunny, StaticRule::Parity, false, 0.25},
    {"bunny-cube-50", Kind::BunnyInCube, kBunny, StaticRule::Parity, false, 0.50},
    {"bunny-cube-75", Kind::BunnyInCube, kBunny, StaticRule::Parity, false, 0.75},
    {"bunny-cube-100", Kind::BunnyInCube, kBunny, StaticRule::Parity, false, 1.0},
    {"bunny-hr", Kind::File, kBunnyHr, StaticRule::AlternatingBorder, false, 1.0},
    {"elephant-gallop", Kind::File, kElephant, StaticRule::AlternatingBorder, false, 1.0},
    {"dragon", Kind::File, kDragon, StaticRule::AlternatingBorder, false, 1.0},
    {"csg3-500k", Kind::CsgOfThree, kDragon, StaticRule::AlternatingBorder, false, 1.0},
}};

/// The files a catalog entry reads from the data folder (none for a demo).
std::vector<std::string> entryFiles(const CatalogEntry& entry)
{
    switch (entry.kind) {
    case Kind::Demo:
        return {};
    case Kind::CsgOfThree:
        return {kDragon, kBunnyHr, kElephant};
    case Kind::File:
    case Kind::BunnyInCube:
        break;
    }
    return {entry.source};
}

const CatalogEntry* findEntry(const std::string& name)
{
    for (const CatalogEntry& entry : kCatalog)
        if (name == entry.name)
            return &entry;
    return nullptr;
}

/// An axis-aligned box, outward (counter-clockwise seen from outside), 12 triangles.
/// Corner i is at min + (bit 0, bit 1, bit 2 of i) × size.
TriangleMesh boxMesh(const glm::dvec3& min, const glm::dvec3& max)
{
    TriangleMesh box;
    for (unsigned i = 0; i < 8; ++i)
        box.positions.emplace_back((i & 1u) ? max.x : min.x, (i & 2u) ? max.y : min.y, (i & 4u) ? max.z : min.z);
    constexpr std::array<std::array<unsigned, 4>, 6> faces = {{
        {0, 4, 6, 2},
        {1, 3, 7, 5},
        {0, 1, 5, 4},
        {2, 6, 7, 3},
        {0, 2, 3, 1},
        {4, 5, 7, 6},
    }};
    for (const auto& f : faces) {
        box.triangles.emplace_back(f[0], f[1], f[2]);
        box.triangles.emplace_back(f[0], f[2], f[3]);
    }
    return box;
}

/// The bunny inside a cube 15 % wider than its largest extent; a plane keeps the lower
/// `keptFraction` of the cube (none for 1).
void addEnclosingCube(LoadedScene& loaded, TrimSettings& settings, double keptFraction)
{
    const Bounds bounds = loaded.scene.worldBounds();
    const glm::dvec3 extent = bounds.max - bounds.min;
    const double half = 0.575 * std::max({extent.x, extent.y, extent.z});
    const glm::dvec3 min = bounds.center() - glm::dvec3(half);
    const glm::dvec3 max = bounds.center() + glm::dvec3(half);
    SceneObject cube{"cube", boxMesh(min, max), glm::dmat4(1.0)};
    loaded.reports.push_back(validateMesh(cube.mesh));
    loaded.scene.objects.push_back(std::move(cube));
    if (keptFraction < 1.0) // keeps y <= cut: -y + cut >= 0
        settings.clip = ClipPlane{true, {0.0, -1.0, 0.0}, min.y + keptFraction * (max.y - min.y)};
}

/// The GPU goal scene of docs/gpu-results.md: about half a million triangles, three CSG
/// operands, trimming, a clipping plane with a hatched cap. The self-crossing dragon once
/// Loop-subdivided (400k triangles, alternating border) united with the elephant (85k) and
/// minus the high-resolution bunny (60k), both parity and placed so that they cross the
/// dragon's body; the plane z <= centre cuts all three open.
BenchScene csgOfThree(const std::string& name, const std::filesystem::path& dataDirectory)
{
    BenchScene scene{name, loadScene((dataDirectory / kDragon).string()), {}};
    SceneObject& dragon = scene.loaded.scene.objects.at(0);
    dragon.mesh = loopSubdivide(dragon.mesh, 1);
    scene.loaded.reports.at(0) = validateMesh(dragon.mesh);
    const Bounds bounds = scene.loaded.scene.worldBounds();
    const glm::dvec3 extent = bounds.max - bounds.min;
    const double size = std::max({extent.x, extent.y, extent.z});
    const glm::dvec3 offset(0.2 * extent.x, 0.0, 0.0);
    const std::array<std::pair<const char*, glm::dvec3>, 2> others = {{
        {kElephant, bounds.center() + offset}, // operand 1
        {kBunnyHr, bounds.center() - offset},  // operand 2
    }};
    for (const auto& [file, center] : others) {
        LoadedScene other = loadScene((dataDirectory / file).string());
        SceneObject object = std::move(other.scene.objects.at(0));
        object.modelMatrix = fitIntoCube(computeBounds(object.mesh), center, 0.55 * size);
        scene.loaded.reports.push_back(validateMesh(object.mesh));
        scene.loaded.scene.objects.push_back(std::move(object));
    }
    scene.settings.rule = StaticRule::AlternatingBorder;
    std::string error;
    const std::optional<CsgExpression> expression = parseCsgExpression("(0 | 1) - 2", &error);
    if (!expression)
        throw std::logic_error("csg3-500k: " + error);
    scene.settings.csg.expression = *expression;
    scene.settings.csg.objectRules[1] = StaticRule::Parity;
    scene.settings.csg.objectRules[2] = StaticRule::Parity;
    scene.settings.clip = ClipPlane{true, {0.0, 0.0, -1.0}, bounds.center().z};
    scene.settings.cap.enabled = true;
    scene.settings.cap.spacing = size / 80.0;
    return scene;
}

BenchScene fromCatalog(const CatalogEntry& entry, const std::filesystem::path& dataDirectory)
{
    if (entry.kind == Kind::CsgOfThree)
        return csgOfThree(entry.name, dataDirectory);
    const std::string source = entry.kind == Kind::Demo ? entry.source : (dataDirectory / entry.source).string();
    BenchScene scene{entry.name, loadScene(source), {}};
    scene.settings.rule = entry.rule;
    if (entry.clipHalf)
        scene.settings.clip = ClipPlane{true, {0.0, 0.0, -1.0}, 0.0};
    if (entry.kind == Kind::BunnyInCube)
        addEnclosingCube(scene.loaded, scene.settings, entry.keptFraction);
    return scene;
}

} // namespace

std::vector<std::string> benchSceneNames()
{
    std::vector<std::string> names;
    for (const CatalogEntry& entry : kCatalog)
        names.emplace_back(entry.name);
    return names;
}

bool isBenchSceneName(const std::string& name)
{
    return findEntry(name) != nullptr;
}

std::filesystem::path defaultBenchDataDirectory()
{
    if (const char* fromEnvironment = std::getenv("TRIMLAB_DATA_DIR"); fromEnvironment && *fromEnvironment)
        return fromEnvironment;
    return TRIMLAB_DEFAULT_DATA_DIR;
}

std::optional<BenchScene> loadBenchScene(const std::string& name, const std::filesystem::path& dataDirectory,
                                         std::string* skipReason)
{
    const CatalogEntry* entry = findEntry(name);
    if (!entry) {
        BenchScene scene{name, loadScene(name), {}};
        scene.settings.trimEnabled = scene.loaded.trimmable();
        return scene;
    }
    for (const std::string& file : entryFiles(*entry)) {
        if (std::filesystem::exists(dataDirectory / file))
            continue;
        if (skipReason)
            *skipReason = (dataDirectory / file).string() + " is missing (the bench reads the shared data "
                                                            "folder; point --data or TRIMLAB_DATA_DIR at it)";
        return std::nullopt;
    }
    BenchScene scene = fromCatalog(*entry, dataDirectory);
    scene.settings.trimEnabled = scene.loaded.trimmable();
    return scene;
}

BenchScene composeBenchScene(const std::vector<std::string>& sources,
                             const std::vector<ObjectTransformOption>& transforms, const TrimSettings& trim)
{
    BenchScene scene{{}, loadScenes(sources), trim};
    scene.name = scene.loaded.displayName;
    // A scene project's CSG and object rules, where --csg and --object-rule gave none.
    adoptSavedCsg(scene.loaded, scene.settings.csg, scene.settings.csg.enabled(), scene.settings.trimEnabled);
    std::optional<QString> error = applyObjectTransforms(transforms, scene.loaded.scene);
    if (!error)
        error = checkObjectIds(trim.csg, scene.loaded.scene.objects.size());
    if (error)
        throw std::invalid_argument(error->toStdString());
    scene.settings.trimEnabled = trim.trimEnabled && scene.loaded.trimmable();
    return scene;
}

} // namespace trimlab::app
