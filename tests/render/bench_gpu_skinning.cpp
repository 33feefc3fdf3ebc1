// Benchmark of one skinned pose, CPU against GPU, side by side in one run: per animation
// and per skinning model (LBS and DQS, pose-to-pose and rest-to-pose, fitted with 20 bones),
// the median time of a pose in playback order
// - on the CPU: one skinning step (skinning_reconstruction.h's blend per vertex, from the
//   previous pose or from the rest pose) plus GpuScene::updatePositions (float conversion,
//   CPU normals, upload), and
// - on the GPU: GpuSkinning::skinPose (transforms upload, skinning and normal passes),
// each followed by glFinish, so both include the GPU's work. The GPU path keeps the chain
// state of the previous pose, as playback does. Not a test: times only.
//
//   xvfb-run -a ./build/tests/render/bench_gpu_skinning [SOURCE [POSES]]
//   (default: the first 40 poses of samba and every pose of elephant-gallop)
#include "skinning_models.h"
#include "test_paths.h"

#include "render/frame/gpu_scene.h"
#include "render/frame/gpu_skinning.h"
#include "render/gl/offscreen_gl_context.h"
#include "render/trim_renderer.h"

#include "core/animation/animation_loader.h"
#include "core/skinning/skinning_reconstruction.h"

#include <QGuiApplication>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace trimlab;

namespace {

constexpr std::size_t kBones = 20;

struct BenchSource {
    std::string pattern;
    std::size_t poses = 0; // 0: all
};

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

struct PoseTimes {
    double cpuSkinMs = 0.0;
    double cpuUploadMs = 0.0;
    double gpuMs = 0.0;
};

// CPU and GPU take turns pose by pose, so a busy machine slows both alike; three rounds
// of playback after one that compiles the GPU's code, medians over every pose.
PoseTimes timePoses(render::TrimRenderer& renderer, const SkinningModel& model)
{
    Scene scene;
    scene.objects.push_back({"skinned", TriangleMesh{{model.restPositions.begin(), model.restPositions.end()},
                                                     model.triangles},
                             glm::dmat4(1.0)});
    renderer.setScene(scene);
    render::GlFunctions& gl = renderer.gl();
    render::GpuScene& gpuScene = renderer.gpuScene();
    const std::vector<std::size_t> order = chainOrder(model.poseCount(), model.restPose);
    render::GpuSkinning skinning(gl, model);
    for (std::size_t t : order)
        skinning.skinPose(gpuScene, 0, t);
    gl.glFinish();

    std::vector<double> skin, upload, gpu;
    std::vector<PosePositions> poses(model.poseCount());
    for (int round = 0; round < 3; ++round)
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
    return {median(skin), median(upload), median(gpu)};
}

const char* methodName(const SkinningModel& model)
{
    return model.method == SkinningMethod::Lbs ? "LBS" : "DQS";
}

const char* chainName(const SkinningModel& model)
{
    return model.chain == SkinningChain::PoseToPose ? "pose-to-pose" : "rest-to-pose";
}

void benchSource(render::TrimRenderer& renderer, const BenchSource& source)
{
    MeshAnimation animation = loadAnimation(source.pattern);
    if (source.poses > 0 && source.poses < animation.poseCount()) {
        animation.poses.resize(source.poses);
        animation.poseNames.resize(std::min(animation.poseNames.size(), source.poses));
        animation.poseTimes.resize(std::min(animation.poseTimes.size(), source.poses));
    }
    const std::filesystem::path path(source.pattern);
    const std::string name = (std::filesystem::is_directory(path) ? path : path.parent_path()).filename().string();
    for (SkinningMethod method : {SkinningMethod::Lbs, SkinningMethod::Dqs})
        for (SkinningChain chain : {SkinningChain::PoseToPose, SkinningChain::RestToPose}) {
            const SkinningModel model = test::fittedModel(animation, kBones, method, chain);
            const PoseTimes times = timePoses(renderer, model);
            const double cpu = times.cpuSkinMs + times.cpuUploadMs;
            std::printf("%-16s %8zu %9zu %5zu %5zu %-4s %-12s %10.2f %10.2f %10.2f %10.2f %8.1f\n", name.c_str(),
                        model.vertexCount(), model.triangles.size(), model.boneCount(), model.poseCount(),
                        methodName(model), chainName(model), times.cpuSkinMs, times.cpuUploadMs, cpu, times.gpuMs,
                        cpu / times.gpuMs);
            std::fflush(stdout);
        }
}

} // namespace

int main(int argc, char** argv)
{
    QGuiApplication application(argc, argv);
    std::vector<BenchSource> sources;
    if (argc > 1)
        sources.push_back({argv[1], argc > 2 ? std::size_t(std::stoul(argv[2])) : 0});
    else
        sources = {{test::sharedDataPath("anim/samba/mesh_00??.obj.gz").string(), 40},
                   {test::sharedDataPath("anim/elephant-gallop").string(), 0}};
    render::OffscreenGlContext context;
    render::TrimRenderer renderer(context.context());
    std::printf("%s\n", renderer.capabilities().summary().toUtf8().constData());
    std::printf("%-16s %8s %8s %5s %5s %-4s %-12s %10s %10s %10s %10s %8s\n", "animation", "vertices", "triangles",
                "bones", "poses", "", "chain", "cpu skin", "cpu upload", "cpu total", "gpu ms", "cpu/gpu");
    for (const BenchSource& source : sources)
        benchSource(renderer, source);
    return 0;
}
