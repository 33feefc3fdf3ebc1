#include "core/skinning/skinning_gltf.h"

#include "core/skinning/skinning_gltf_parts.h"
#include "core/io/gltf_builder.h"
#include "core/io/atomic_write.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace trimlab {

namespace skinning_gltf {

std::vector<glm::vec3> toFloat(const std::vector<glm::dvec3>& positions)
{
    return std::vector<glm::vec3>(positions.begin(), positions.end());
}

} // namespace skinning_gltf

namespace {

void requireExportable(const SkinningModel& model, double fps, const SkinExportOptions& options)
{
    auto fail = [](const std::string& what) { throw std::invalid_argument("skinned glTF export: " + what); };
    if (!(std::isfinite(fps) && fps > 0.0))
        fail("fps must be finite and > 0, not " + std::to_string(fps));
    if (model.poseCount() == 0 || model.vertexCount() == 0 || model.triangles.empty())
        fail("the model has no poses, vertices or triangles");
    if (model.weights.vertices.size() != model.vertexCount())
        fail(std::to_string(model.weights.vertices.size()) + " weighted vertices for " +
             std::to_string(model.vertexCount()) + " rest positions");
    if (model.boneCount() == 0 || model.boneCount() > 65535)
        fail(std::to_string(model.boneCount()) + " bones; JOINTS_0 holds 1 to 65535");
    requireConvexWeights(model.weights, 1e-6);
    for (std::size_t t = 0; t < model.poseCount(); ++t) {
        const std::size_t n = model.method == SkinningMethod::Lbs ? model.affine[t].size() : model.rigid[t].size();
        if (n != model.boneCount())
            fail("pose " + std::to_string(t) + " has " + std::to_string(n) + " bone transforms for " +
                 std::to_string(model.boneCount()) + " bones");
    }
    for (const glm::uvec3& f : model.triangles)
        if (std::max({f.x, f.y, f.z}) >= model.vertexCount())
            fail("a triangle names a vertex ≥ " + std::to_string(model.vertexCount()));
    if (options.target && options.target->size() != model.poseCount())
        fail(std::to_string(options.target->size()) + " target poses for " + std::to_string(model.poseCount()));
}

// Keyframe t at t/fps, strictly increasing once rounded to float.
std::vector<float> keyframeTimes(std::size_t poses, double fps)
{
    std::vector<float> times(poses);
    for (std::size_t t = 0; t < poses; ++t) {
        times[t] = float(double(t) / fps);
        if (t > 0 && !(times[t] > times[t - 1]))
            throw std::invalid_argument("skinned glTF export: " + std::to_string(poses) + " poses at " +
                                        std::to_string(fps) + " fps give keyframe times float cannot tell apart");
    }
    return times;
}

tinygltf::Model meshModel(const SkinningModel& skinning)
{
    tinygltf::Model model;
    model.asset.generator = "TrimLab skinning export";
    model.buffers.emplace_back();
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.attributes["POSITION"] = io::addGltfVec3Accessor(model, skinning_gltf::toFloat(skinning.restPositions),
                                                               TINYGLTF_TARGET_ARRAY_BUFFER, true);
    primitive.indices = io::addGltfTriangleIndices(model, skinning.triangles);
    io::addGltfSingleMeshScene(model, primitive, "skinned mesh");
    return model;
}

bool hasGlbExtension(const std::filesystem::path& path)
{
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".glb";
}

} // namespace

std::string_view skinExportKindName(SkinExportKind kind)
{
    switch (kind) {
    case SkinExportKind::RigidTransforms:
        return "rigid transforms";
    case SkinExportKind::RigidApproximation:
        return "rigid approximation of an affine fit";
    case SkinExportKind::MorphTargets:
        return "morph targets";
    }
    return "unknown";
}

SkinnedGltf skinnedGltf(const SkinningModel& model, double fps, bool binary, const SkinExportOptions& options)
{
    requireExportable(model, fps, options);
    const std::vector<float> times = keyframeTimes(model.poseCount(), fps);
    tinygltf::Model gltf = meshModel(model);
    SkinnedGltf result;
    if (options.morphTargets) {
        result.report = skinning_gltf::addMorphTargets(gltf, model, times);
    } else if (options.target) {
        result.report = skinning_gltf::addSkin(gltf, model, *options.target, times, options.stepInterpolation);
    } else {
        result.report = skinning_gltf::addSkin(gltf, model, reconstructPoses(model), times, options.stepInterpolation);
    }
    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&gltf, out, !binary, binary))
        throw std::runtime_error("tinygltf could not serialise the skinned animation");
    result.bytes = out.str();
    return result;
}

ExportedSkin exportSkinnedGltf(const SkinningModel& model, const std::filesystem::path& path, double fps,
                               const SkinExportOptions& options)
{
    SkinnedGltf gltf = skinnedGltf(model, fps, hasGlbExtension(path), options);
    io::writeFileAtomically(path, gltf.bytes);
    return std::move(gltf.report);
}

} // namespace trimlab
