#include "core/animation/animation_segmenter.h"

#include "core/animation/over_segmentation.h"
#include "core/util/parallel_for.h"
#include "core/animation/vertex_areas.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>

namespace trimlab {

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Restores a pose when the work that follows a change throws (strong guarantee).
class PoseRollback {
public:
    PoseRollback(MeshAnimation& animation, std::size_t pose, std::vector<glm::vec3> previous)
        : m_animation(animation), m_pose(pose), m_previous(std::move(previous))
    {
    }
    ~PoseRollback()
    {
        if (m_armed)
            m_animation.poses[m_pose] = std::move(m_previous);
    }
    PoseRollback(const PoseRollback&) = delete;
    PoseRollback& operator=(const PoseRollback&) = delete;
    void release() { m_armed = false; }

private:
    MeshAnimation& m_animation;
    std::size_t m_pose;
    std::vector<glm::vec3> m_previous;
    bool m_armed = true;
};

} // namespace

AnimationSegmenter::AnimationSegmenter(MeshAnimation animation, SegmenterSettings settings)
    : m_animation(std::move(animation)), m_settings(settings)
{
    requireWellFormed(m_animation);
    if (m_settings.partition.clusters < 1)
        throw std::invalid_argument("AnimationSegmenter: at least 1 cluster per pose is needed");
    m_graph = std::make_shared<const VertexGraph>(buildVertexGraph(m_animation.vertexCount(), m_animation.triangles));
    m_areas = trimlab::vertexAreas(m_animation.poses[m_animation.restPose], m_animation.triangles);
}

std::vector<PoseFeature> AnimationSegmenter::computeFeatures(const std::vector<std::size_t>& poses,
                                                             const TaskControl& control, double& ms) const
{
    const auto start = std::chrono::steady_clock::now();
    std::vector<PoseFeature> features(poses.size());
    parallelFor(
        poses.size(), m_settings.threads,
        [&](std::size_t i) { features[i] = computePoseFeature(m_animation, poses[i], m_settings.feature); }, control,
        "features");
    ms = millisecondsSince(start);
    return features;
}

std::vector<VertexLabeling> AnimationSegmenter::computePartitions(const std::vector<PoseFeature>& features,
                                                                  const PartitionSettings& settings,
                                                                  const TaskControl& control, double& ms) const
{
    const auto start = std::chrono::steady_clock::now();
    std::vector<VertexLabeling> partitions(features.size());
    parallelFor(
        features.size(), m_settings.threads,
        [&](std::size_t i) { partitions[i] = partitionPose(*m_graph, features[i], m_areas, settings); }, control,
        "partitions");
    ms = millisecondsSince(start);
    return partitions;
}

void AnimationSegmenter::commitJoin(std::unique_ptr<PoseJoin> join, double startMs)
{
    const auto start = std::chrono::steady_clock::now();
    m_cleaner = std::make_unique<P2pCleaner>(*join, m_areas);
    m_join = std::move(join);
    m_times.overSegmentationMs = startMs + millisecondsSince(start);
}

void AnimationSegmenter::run(const TaskControl& control)
{
    const std::vector<std::size_t> poses =
        featurePoses(m_animation.poseCount(), m_animation.restPose, m_settings.feature);
    SegmentationTimes times;
    std::vector<PoseFeature> features = computeFeatures(poses, control, times.featuresMs);
    std::vector<VertexLabeling> partitions =
        computePartitions(features, m_settings.partition, control, times.partitionsMs);
    const auto start = std::chrono::steady_clock::now();
    auto join = std::make_unique<PoseJoin>(m_graph);
    for (VertexLabeling& partition : partitions)
        join->append(std::move(partition));
    const double joinMs = millisecondsSince(start);
    m_featurePoses = poses;
    m_features = std::move(features);
    m_times = times;
    commitJoin(std::move(join), joinMs);
}

void AnimationSegmenter::repartition(const PartitionSettings& settings, const TaskControl& control)
{
    if (!ready())
        throw std::logic_error("AnimationSegmenter::repartition before run()");
    if (settings.clusters < 1)
        throw std::invalid_argument("AnimationSegmenter: at least 1 cluster per pose is needed");
    SegmentationTimes times;
    std::vector<VertexLabeling> partitions = computePartitions(m_features, settings, control, times.partitionsMs);
    const auto start = std::chrono::steady_clock::now();
    auto join = std::make_unique<PoseJoin>(m_graph);
    for (VertexLabeling& partition : partitions)
        join->append(std::move(partition));
    m_settings.partition = settings;
    m_times = times;
    commitJoin(std::move(join), millisecondsSince(start));
}

void AnimationSegmenter::appendPose(std::vector<glm::vec3> positions, std::string name, const TaskControl& control)
{
    if (!ready())
        throw std::logic_error("AnimationSegmenter::appendPose before run()");
    if (positions.size() != m_animation.vertexCount())
        throw std::invalid_argument("appendPose: the pose has " + std::to_string(positions.size()) +
                                    " vertices but the animation has " + std::to_string(m_animation.vertexCount()));
    m_animation.poses.push_back(std::move(positions));
    std::vector<std::size_t> added;
    try {
        const std::vector<std::size_t> all =
            featurePoses(m_animation.poseCount(), m_animation.restPose, m_settings.feature);
        added.assign(all.begin() + std::ptrdiff_t(m_featurePoses.size()), all.end());
        SegmentationTimes times;
        std::vector<PoseFeature> features = computeFeatures(added, control, times.featuresMs);
        std::vector<VertexLabeling> partitions =
            computePartitions(features, m_settings.partition, control, times.partitionsMs);
        const auto start = std::chrono::steady_clock::now();
        for (VertexLabeling& partition : partitions)
            m_join->append(std::move(partition));
        m_features.insert(m_features.end(), std::make_move_iterator(features.begin()),
                          std::make_move_iterator(features.end()));
        m_featurePoses = all;
        m_times = times;
        commitJoin(std::move(m_join), millisecondsSince(start));
    } catch (...) {
        m_animation.poses.pop_back();
        throw;
    }
    if (!m_animation.poseNames.empty())
        m_animation.poseNames.push_back(name.empty() ? "pose " + std::to_string(m_animation.poseCount() - 1) : name);
    if (!m_animation.poseTimes.empty())
        m_animation.poseTimes.push_back(m_animation.poseTimes.back() + 1.0);
}

void AnimationSegmenter::editPose(std::size_t pose, std::vector<glm::vec3> positions, const TaskControl& control)
{
    if (!ready())
        throw std::logic_error("AnimationSegmenter::editPose before run()");
    if (pose >= m_animation.poseCount() || positions.size() != m_animation.vertexCount())
        throw std::invalid_argument("editPose: no pose " + std::to_string(pose) + " or a wrong vertex count");
    PoseRollback rollback(m_animation, pose, std::exchange(m_animation.poses[pose], std::move(positions)));
    if (pose == m_animation.restPose) {
        // The rest pose gives the areas every partition is weighted by: recompute all.
        std::vector<double> previousAreas =
            std::exchange(m_areas, trimlab::vertexAreas(m_animation.poses[pose], m_animation.triangles));
        try {
            run(control);
        } catch (...) {
            m_areas = std::move(previousAreas);
            throw;
        }
        rollback.release();
        return;
    }
    const std::vector<std::size_t> affected =
        posesAffectedByEdit(m_animation.poseCount(), m_animation.restPose, pose, m_settings.feature);
    SegmentationTimes times;
    std::vector<PoseFeature> features = computeFeatures(affected, control, times.featuresMs);
    std::vector<VertexLabeling> partitions =
        computePartitions(features, m_settings.partition, control, times.partitionsMs);
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::pair<std::size_t, VertexLabeling>> replaced;
    for (std::size_t i = 0; i < affected.size(); ++i) {
        const auto index = std::size_t(std::lower_bound(m_featurePoses.begin(), m_featurePoses.end(), affected[i]) -
                                       m_featurePoses.begin());
        replaced.emplace_back(index, std::move(partitions[i]));
        m_features[index] = std::move(features[i]);
    }
    rollback.release();
    m_join->replace(std::move(replaced));
    m_times = times;
    commitJoin(std::move(m_join), millisecondsSince(start));
}

VertexLabeling AnimationSegmenter::segment(double h) const
{
    if (!ready())
        throw std::logic_error("AnimationSegmenter::segment before run()");
    return m_cleaner->clean(std::clamp(h, 0.0, 1.0));
}

std::vector<VertexLabeling> AnimationSegmenter::variableSegmentation() const
{
    if (!ready())
        throw std::logic_error("AnimationSegmenter::variableSegmentation before run()");
    std::vector<VertexLabeling> result;
    const std::size_t k = m_join->partitionCount();
    for (std::size_t i = 0; i < k; ++i) {
        result.push_back(i + 1 < k ? joinLabelings(*m_graph, m_join->partition(i), m_join->partition(i + 1))
                                   : m_join->partition(i));
    }
    return result;
}

} // namespace trimlab
