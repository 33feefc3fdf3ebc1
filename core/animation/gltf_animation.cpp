#include "core/animation/gltf_animation.h"

#include "core/animation/gltf_animated_geometry.h"
#include "core/animation/gltf_animation_clip.h"
#include "core/animation/gltf_node_transforms.h"
#include "core/animation/pose_welding.h"
#include "core/mesh/gltf_document.h"
#include "core/mesh/gzip_input.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/mesh_load_error.h"
#include "core/mesh/reader_support.h"
#include "core/util/memory_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace trimlab {

namespace {

std::vector<double> sampleTimes(const GltfAnimationClip& clip, double fps, const std::string& name)
{
    if (!std::isfinite(fps) || fps < 0.0)
        throw MeshLoadError(name, "the frame rate must be a positive number (or 0 for the keyframe times)");
    if (fps == 0.0)
        return clip.keyframeTimes;
    const double start = clip.keyframeTimes.front();
    const double span = clip.keyframeTimes.back() - start;
    const double frames = std::floor(span * fps + 1e-9) + 1.0;
    if (frames > double(kMaxSampledPoses))
        throw MeshLoadError(name, "sampling " + std::to_string(span) + " s at " + std::to_string(fps) +
                                      " fps gives more than " + std::to_string(kMaxSampledPoses) + " poses");
    std::vector<double> times;
    for (std::size_t i = 0; i < std::size_t(frames); ++i)
        times.push_back(start + double(i) / fps);
    return times;
}

std::string poseName(const std::string& clip, double time)
{
    char text[64];
    std::snprintf(text, sizeof text, " t=%.3f s", time);
    return clip + text;
}

std::vector<glm::vec3> toFloatPositions(const std::vector<glm::dvec3>& positions, const std::string& name,
                                        const std::string& pose)
{
    std::vector<glm::vec3> result;
    result.reserve(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) {
        const glm::dvec3& p = positions[v];
        if (!isFiniteFloat(p.x) || !isFiniteFloat(p.y) || !isFiniteFloat(p.z))
            throw MeshLoadError(name, "vertex " + std::to_string(v) + " of pose '" + pose +
                                          "' is not finite after skinning (check the skin's matrices and weights)");
        result.emplace_back(p);
    }
    return result;
}

std::string readFileBytes(const std::filesystem::path& path, const std::string& name)
{
    std::string bytes = readMeshInputFile(path, name);
    if (bytes.empty())
        throw MeshLoadError(name, "the file is empty (0 bytes)");
    return bytes;
}

// The skin of `geometry` when one skin poses every vertex and nothing else moves them:
// no morph targets, every primitive skinned by the same skin, every vertex weighted.
// Joint matrices come per pose later.
std::optional<AnimationSkin> singleSkin(const GltfAnimatedGeometry& geometry)
{
    if (geometry.primitives.empty())
        return std::nullopt;
    const int skinIndex = geometry.primitives.front().skin;
    std::size_t influences = 0;
    for (const GltfPrimitiveInstance& prim : geometry.primitives) {
        if (prim.skin < 0 || prim.skin != skinIndex || !prim.targets.empty())
            return std::nullopt;
        influences = std::max(influences, prim.influences);
    }
    AnimationSkin skin;
    skin.jointCount = geometry.skins[std::size_t(skinIndex)].joints.size();
    skin.influences = influences;
    for (const GltfPrimitiveInstance& prim : geometry.primitives)
        for (std::size_t v = 0; v < prim.base.size(); ++v) {
            skin.bindPositions.push_back(prim.base[v]);
            double total = 0.0;
            for (std::size_t i = 0; i < prim.influences; ++i)
                total += prim.weights[v * prim.influences + i];
            if (!(total > 0.0))
                return std::nullopt; // the loader poses it by its node instead
            for (std::size_t i = 0; i < influences; ++i) {
                const bool present = i < prim.influences;
                skin.joints.push_back(present ? prim.joints[v * prim.influences + i] : 0u);
                skin.weights.push_back(present ? prim.weights[v * prim.influences + i] / total : 0.0);
            }
        }
    return skin;
}

} // namespace

MeshAnimation readGltfAnimation(std::string_view bytes, const std::string& displayName,
                                const std::filesystem::path& baseDir, const GltfAnimationOptions& options,
                                const TaskControl& control)
{
    const std::string plain = hasGzipMagic(bytes) ? gunzip(bytes, displayName, kMaxMeshInputBytes) : std::string(bytes);
    const tinygltf::Model model = parseGltfDocument(plain, displayName, baseDir);
    const GltfAnimationClip clip = readAnimationClip(model, options.animation, displayName);
    const std::vector<int> parents = nodeParents(model, displayName);
    const GltfAnimatedGeometry geometry = readAnimatedGeometry(model, parents, displayName);
    const std::vector<NodeTransform> fileNodes = fileNodeTransforms(model, displayName);
    const std::vector<double> times = sampleTimes(clip, options.fps, displayName);
    MeshAnimation animation;
    animation.triangles = geometry.triangles;
    requireMemory(std::uint64_t(times.size()) * geometry.vertexCount * sizeof(glm::vec3),
                  displayName + ": " + std::to_string(times.size()) + " poses of " +
                      std::to_string(geometry.vertexCount) + " vertices",
                  "sample the clip at a lower rate (--fps)");
    std::optional<AnimationSkin> skin = singleSkin(geometry);
    for (std::size_t i = 0; i < times.size(); ++i) {
        control.throwIfCancelled();
        std::vector<NodeTransform> nodes = fileNodes;
        clip.apply(times[i], nodes);
        const std::vector<glm::dmat4> world = worldMatrices(nodes, parents);
        animation.poseNames.push_back(poseName(clip.name, times[i]));
        animation.poses.push_back(
            toFloatPositions(geometry.pose(nodes, world), displayName, animation.poseNames.back()));
        animation.poseTimes.push_back(times[i]);
        if (skin)
            skin->jointMatrices.push_back(
                jointMatrices(geometry.skins[std::size_t(geometry.primitives.front().skin)], world));
        control.report("load", i + 1, times.size());
    }
    std::vector<std::size_t> kept;
    MeshAnimation welded = weldAcrossPoses(animation, &kept);
    if (skin)
        welded.skin = std::make_shared<const AnimationSkin>(keepSkinVertices(*skin, kept));
    return welded;
}

MeshAnimation loadGltfAnimation(const std::filesystem::path& path, const GltfAnimationOptions& options,
                                const TaskControl& control)
{
    const std::string name = path.string();
    std::filesystem::path baseDir = path.parent_path();
    if (baseDir.empty())
        baseDir = ".";
    return readGltfAnimation(readFileBytes(path, name), name, baseDir, options, control);
}

} // namespace trimlab
