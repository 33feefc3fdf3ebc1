#include "app/bench_skinning.h"

#include "render/frame/gpu_scene.h"
#include "render/frame/gpu_skinning.h"

#include "core/animation/animation_loader.h"
#include "core/mesh/triangle_mesh.h"
#include "core/skinning/seed_bones.h"
#include "core/skinning/skinning_reconstruction.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>

namespace trimlab::app {

namespace {

constexpr std::size_t kBones = 20;

struct SkinningScene {
    const char* name;
    const char* source; ///< relative to the data folder: a folder or a file pattern
    std::size_t poses;  ///< 0: all
};

constexpr SkinningScene kScenes[] = {
    {"skinning:samba", "anim/samba/mesh_00??.obj.gz", 40},
    {"skinning:elephant-gallop", "anim/elephant-gallop", 0},
};

const SkinningScene* findScene(const std::string& name)
{
    for (const SkinningScene& scene : kScenes)
        if (name == scene.name)
            return &scene;
    return nullptr;
}

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

// One CPU skinning step: pose `pose` from the positions of its previous pose (or the rest
// pose), as a renderer without GPU skinning computes it during playback.
PosePositions cpuStep(const SkinningModel& model, std::size_t pose, const PosePositions& previous)
{
    const PosePositions& source = model.chain == SkinningChain::RestToPose ? model.restPositions : previous;
    if (pose == model.restPose && !restPoseMoves(model))
        return model.restPositions;
    PosePositions positions(source.size());
    for (std::size_t j = 0; j < source.size(); ++j)
        positions[j] = blendedTransform(model, pose, j).apply(source[j]);
    return positions;
}

double largestDistance(const std::vector<glm::vec3>& gpu, const PosePositions& cpu)
{
    double largest = 0.0;
    for (std::size_t v = 0; v < gpu.size(); ++v)
        largest = std::max(largest, glm::length(glm::dvec3(gpu[v]) - cpu[v]));
    return largest;
}

SkinningBenchRow timeModel(render::TrimRenderer& renderer, const SkinningModel& model, int rounds)
{
    Scene scene;
    scene.objects.push_back({"skinned",
                             TriangleMesh{{model.restPositions.begin(), model.restPositions.end()}, model.triangles},
                             glm::dmat4(1.0)});
    const double diagonal = 2.0 * computeBounds(scene.objects.front().mesh).radius();
    renderer.setScene(scene);
    render::GlFunctions& gl = renderer.gl();
    render::GpuScene& gpuScene = renderer.gpuScene();
    const std::vector<std::size_t> order = chainOrder(model.poseCount(), model.restPose);
    render::GpuSkinning skinning(gl, model);

    // The first round compiles the GPU's code and checks every pose against the CPU's.
    SkinningBenchRow row;
    std::vector<PosePositions> poses(model.poseCount());
    for (std::size_t t : order) {
        poses[t] = cpuStep(model, t, poses[model.previousPose(t)]);
        skinning.skinPose(gpuScene, 0, t);
        row.largestDeviation = std::max(row.largestDeviation, largestDistance(gpuScene.readPositions(0), poses[t]));
    }
    row.largestDeviation /= std::max(diagonal, 1e-300);

    std::vector<double> skin, upload, gpu;
    for (int round = 0; round < rounds; ++round)
        for (std::size_t t : order) {
            auto start = std::chrono::steady_clock::now();
            poses[t] = cpuStep(model, t, poses[model.previousPose(t)]);
            const std::vector<glm::vec3> floats(poses[t].begin(), poses[t].end());
            skin.push_back(millisecondsSince(start));
            start = std::chrono::steady_clock::now();
            gpuScene.updatePositions(0, floats);
            gl.glFinish();
            upload.push_back(millisecondsSince(start));
            start = std::chrono::steady_clock::now();
            skinning.skinPose(gpuScene, 0, t);
            gl.glFinish();
            gpu.push_back(millisecondsSince(start));
        }
    row.cpuSkinMs = median(skin);
    row.cpuUploadMs = median(upload);
    row.gpuMs = median(gpu);
    return row;
}

} // namespace

std::vector<std::string> skinningBenchSceneNames()
{
    std::vector<std::string> names;
    for (const SkinningScene& scene : kScenes)
        names.emplace_back(scene.name);
    return names;
}

std::string skinningBenchSceneNamesText()
{
    std::string text;
    for (const std::string& name : skinningBenchSceneNames())
        text += (text.empty() ? "" : ", ") + name;
    return text;
}

bool isSkinningBenchScene(const std::string& name)
{
    return findScene(name) != nullptr;
}

std::optional<MeshAnimation>
loadSkinningBenchAnimation(const std::string& name, const std::filesystem::path& dataDirectory, std::string* skipReason)
{
    const SkinningScene* scene = findScene(name);
    if (!scene)
        throw std::invalid_argument("unknown animation scene " + name);
    const std::filesystem::path source = dataDirectory / scene->source;
    const std::filesystem::path folder =
        source.filename().string().find('?') != std::string::npos ? source.parent_path() : source;
    if (!std::filesystem::is_directory(folder)) {
        if (skipReason)
            *skipReason = folder.string() + " is missing";
        return std::nullopt;
    }
    MeshAnimation animation = loadAnimation(source.string());
    if (scene->poses > 0 && scene->poses < animation.poseCount()) {
        animation.poses.resize(scene->poses);
        animation.poseNames.resize(std::min(animation.poseNames.size(), scene->poses));
        animation.poseTimes.resize(std::min(animation.poseTimes.size(), scene->poses));
        animation.skin.reset();
    }
    return animation;
}

std::vector<SkinningBenchRow> measureSkinning(render::TrimRenderer& renderer, const MeshAnimation& animation,
                                              const QString& name, int rounds)
{
    std::vector<SkinningBenchRow> rows;
    for (SkinningMethod method : {SkinningMethod::Lbs, SkinningMethod::Dqs})
        for (SkinningChain chain : {SkinningChain::PoseToPose, SkinningChain::RestToPose}) {
            const SkinningModel model = seedBoneModel(animation, kBones, method, chain);
            SkinningBenchRow row = timeModel(renderer, model, rounds);
            row.animation = name;
            row.vertices = model.vertexCount();
            row.triangles = model.triangles.size();
            row.bones = model.boneCount();
            row.poses = model.poseCount();
            row.method = method == SkinningMethod::Lbs ? QStringLiteral("LBS") : QStringLiteral("DQS");
            row.chain =
                chain == SkinningChain::PoseToPose ? QStringLiteral("pose-to-pose") : QStringLiteral("rest-to-pose");
            rows.push_back(row);
        }
    return rows;
}

QStringList skinningTableLines(const std::vector<SkinningBenchRow>& rows)
{
    QStringList lines;
    if (rows.empty())
        return lines;
    lines << QStringLiteral("Skinned poses, ms per pose (medians): CPU skinning + upload against GPU skinning");
    lines << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9 %10 %11 %12")
                 .arg(QStringLiteral("scene"), -26)
                 .arg(QStringLiteral("vertices"), 8)
                 .arg(QStringLiteral("bones"), 5)
                 .arg(QStringLiteral("poses"), 5)
                 .arg(QStringLiteral(""), -3)
                 .arg(QStringLiteral("chain"), -12)
                 .arg(QStringLiteral("cpu skin"), 9)
                 .arg(QStringLiteral("cpu upload"), 10)
                 .arg(QStringLiteral("cpu total"), 9)
                 .arg(QStringLiteral("gpu"), 9)
                 .arg(QStringLiteral("cpu/gpu"), 7)
                 .arg(QStringLiteral("gpu vs cpu"), 10);
    for (const SkinningBenchRow& row : rows) {
        const double cpu = row.cpuSkinMs + row.cpuUploadMs;
        lines << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9 %10 %11 %12")
                     .arg(row.animation, -26)
                     .arg(row.vertices, 8)
                     .arg(row.bones, 5)
                     .arg(row.poses, 5)
                     .arg(row.method, -3)
                     .arg(row.chain, -12)
                     .arg(row.cpuSkinMs, 9, 'f', 2)
                     .arg(row.cpuUploadMs, 10, 'f', 2)
                     .arg(cpu, 9, 'f', 2)
                     .arg(row.gpuMs, 9, 'f', 2)
                     .arg(row.gpuMs > 0.0 ? cpu / row.gpuMs : 0.0, 7, 'f', 2)
                     .arg(QStringLiteral("%1").arg(row.largestDeviation, 0, 'e', 1), 10);
    }
    lines << QStringLiteral("gpu vs cpu: the largest distance of a GPU-skinned vertex from the CPU's over every pose, "
                            "as a fraction of the bounding-box diagonal (at most 1e-5, or the bench fails)");
    return lines;
}

} // namespace trimlab::app
