#include "app/bench_scenes.h"

#include "core/mesh/mesh_validation.h"

#include <algorithm>
#include <array>
#include <cstdlib>

namespace trimlab::app {

namespace {

/// How a catalog scene is built.
enum class Kind { Demo, File, BunnyInCube };

struct CatalogEntry {
    const char* name;
    Kind kind;
    const char* source;   ///< demo:NAME, or a path relative to the data folder
    StaticRule rule;
    bool clipHalf;        ///< keep z <= 0 (the GUI's first clipping plane)
    double keptFraction;  ///< BunnyInCube: the part of the cube's height kept, from below
};

constexpr const char* kBunny = "static/odedstein-bunny.obj.gz";

constexpr std::array<CatalogEntry, 10> kCatalog = {{
    {"demo:pushed-sphere", Kind::Demo, "demo:pushed-sphere", StaticRule::AlternatingBorder, true, 1.0},
    {"demo:crossing-loop", Kind::Demo, "demo:crossing-loop", StaticRule::AlternatingBorder, false, 1.0},
    {"demo:nested-spheres", Kind::Demo, "demo:nested-spheres", StaticRule::Parity, true, 1.0},
    {"bunny-cube-25", Kind::BunnyInCube, kBunny, StaticRule::Parity, false, 0.25},
    {"bunny-cube-50", Kind::BunnyInCube, kBunny, StaticRule::Parity, false, 0.50},
    {"bunny-cube-75", Kind::BunnyInCube, kBunny, StaticRule::Parity, false, 0.75},
    {"bunny-cube-100", Kind::BunnyInCube, kBunny, StaticRule::Parity, false, 1.0},
    {"bunny-hr", Kind::File, "static/odedstein-bunny_hr.obj.gz", StaticRule::AlternatingBorder, false, 1.0},
    {"elephant-gallop", Kind::File, "anim/elephant-gallop/elephant-gallop-05.obj.gz", StaticRule::AlternatingBorder,
     false, 1.0},
    {"dragon", Kind::File, "selfintersect/quartet-dragon.obj.gz", StaticRule::AlternatingBorder, false, 1.0},
}};

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
        {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6},
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

BenchScene fromCatalog(const CatalogEntry& entry, const std::filesystem::path& dataDirectory)
{
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
    if (entry->kind != Kind::Demo && !std::filesystem::exists(dataDirectory / entry->source)) {
        if (skipReason)
            *skipReason = (dataDirectory / entry->source).string() + " is missing (the bench reads the shared data "
                                                                     "folder; point --data or TRIMLAB_DATA_DIR at it)";
        return std::nullopt;
    }
    BenchScene scene = fromCatalog(*entry, dataDirectory);
    scene.settings.trimEnabled = scene.loaded.trimmable();
    return scene;
}

} // namespace trimlab::app
