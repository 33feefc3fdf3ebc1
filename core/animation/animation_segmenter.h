#pragma once
/// \file
/// The segmentation pipeline of thesis chapter 3 as one object a panel or a batch verb
/// drives: per-pose features and partitions (in parallel, with progress and cancel), their
/// join into the over-segmentation, and p2p-cleaning for any h without recomputing
/// anything else. Poses can be appended (real-time segmentation, 3.2.2) and edited (3.2.6)
/// with only the affected partitions recomputed.
///
/// How a panel drives it (all calls but segment() and the accessors belong on a worker
/// thread; TaskControl carries progress and a stop token):
///   MeshAnimation a = loadAnimation(source, loadOptions, control);     // animation_loader.h
///   AnimationSegmenter s(std::move(a), settings);
///   s.run(control);                                     // features + partitions + join
///   VertexLabeling seg = s.segment(h);                  // slider: ~1 ms, any thread
///   colors = colorSegments(s.graph(), seg, s.vertexAreas());            // first time
///   colors = propagateColors(s.graph(), s.vertexAreas(), old, oldColors, seg); // on h change
///   vertexColors(seg, colors) / faceLabels(triangles, seg)    // display buffers
///   s.appendPose(p) / s.editPose(i, p) / s.repartition(settings.partition, control);
///   segmentationJson / segmentationCsv / writeSegmentationGltf  // export

#include "core/animation/mesh_animation.h"
#include "core/animation/p2p_cleaning.h"
#include "core/animation/pose_features.h"
#include "core/animation/pose_join.h"
#include "core/animation/pose_partition.h"
#include "core/util/task_control.h"
#include "core/animation/vertex_graph.h"

#include <glm/vec3.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace trimlab {

struct SegmenterSettings {
    FeatureSettings feature;
    PartitionSettings partition;
    unsigned threads = 0; ///< worker threads for features and partitions (0 = hardware)
};

/// Wall-clock milliseconds of the stages of the last run() (or of the last append/edit,
/// which recompute only what they must).
struct SegmentationTimes {
    double featuresMs = 0.0;
    double partitionsMs = 0.0;
    double overSegmentationMs = 0.0; ///< joining the partitions + preparing the cleaner
};

class AnimationSegmenter {
public:
    /// Takes the animation (requireWellFormed) and prepares the vertex graph and the
    /// rest-pose vertex areas; computes nothing else yet. Throws std::invalid_argument for a
    /// malformed animation or fewer than 1 cluster.
    AnimationSegmenter(MeshAnimation animation, SegmenterSettings settings);

    /// Offline segmentation: features and partitions of every feature pose in parallel,
    /// then their join. Progress stages "features" and "partitions" (one item per pose).
    /// On OperationCancelled (or any exception) the segmenter keeps its previous state.
    void run(const TaskControl& control = {});

    /// Re-partitions with other partition settings, reusing the features of the last run
    /// (a cluster-count spin box). Same guarantees as run(); run() must have been called.
    void repartition(const PartitionSettings& settings, const TaskControl& control = {});

    /// Real-time segmentation (3.2.2): appends a pose (#V positions), computes the feature
    /// and partition of the pose(s) this makes available (featurePoses) and joins them with
    /// the over-segmentation so far. After the last pose the state equals run() on the
    /// whole animation. run() must have been called (it may have had a single pose).
    /// Throws std::invalid_argument for a wrong vertex count.
    void appendPose(std::vector<glm::vec3> positions, std::string name = {}, const TaskControl& control = {});

    /// Edit propagation (3.2.6): replaces pose `pose` and recomputes only the features and
    /// partitions that depend on it (posesAffectedByEdit), then re-joins; editing the rest
    /// pose recomputes everything, since its areas weight every partition. Equals run() on
    /// the edited animation. Same guarantees as run().
    void editPose(std::size_t pose, std::vector<glm::vec3> positions, const TaskControl& control = {});

    /// p2p-cleaning for `h` ∈ [0, 1] (values outside are clamped): fast, const, safe to
    /// call from several threads. Requires ready().
    [[nodiscard]] VertexLabeling segment(double h) const;

    /// Variable segmentation (3.2.3): for every feature pose its partition joined with the
    /// next one's (the last pose: its own partition), not cleaned.
    [[nodiscard]] std::vector<VertexLabeling> variableSegmentation() const;

    [[nodiscard]] bool ready() const { return m_join != nullptr; }
    [[nodiscard]] const MeshAnimation& animation() const { return m_animation; }
    [[nodiscard]] const SegmenterSettings& settings() const { return m_settings; }
    [[nodiscard]] const VertexGraph& graph() const { return *m_graph; }
    [[nodiscard]] const std::shared_ptr<const VertexGraph>& sharedGraph() const { return m_graph; }
    /// #V barycentric areas of the rest pose.
    [[nodiscard]] const std::vector<double>& vertexAreas() const { return m_areas; }
    /// The pose index of each partition (featurePoses), in join order.
    [[nodiscard]] const std::vector<std::size_t>& partitionedPoses() const { return m_featurePoses; }
    /// The features of the partitioned poses (same order).
    [[nodiscard]] const std::vector<PoseFeature>& features() const { return m_features; }
    /// Partitions and prefix over-segmentations. Requires ready().
    [[nodiscard]] const PoseJoin& join() const { return *m_join; }
    [[nodiscard]] const VertexLabeling& overSegmentation() const { return m_join->overSegmentation(); }
    [[nodiscard]] const P2pCleaner& cleaner() const { return *m_cleaner; }
    [[nodiscard]] const SegmentationTimes& times() const { return m_times; }

private:
    [[nodiscard]] std::vector<PoseFeature> computeFeatures(const std::vector<std::size_t>& poses,
                                                           const TaskControl& control, double& ms) const;
    [[nodiscard]] std::vector<VertexLabeling> computePartitions(const std::vector<PoseFeature>& features,
                                                                const PartitionSettings& settings,
                                                                const TaskControl& control, double& ms) const;
    void commitJoin(std::unique_ptr<PoseJoin> join, double startMs);

    MeshAnimation m_animation;
    SegmenterSettings m_settings;
    std::shared_ptr<const VertexGraph> m_graph;
    std::vector<double> m_areas;
    std::vector<std::size_t> m_featurePoses;
    std::vector<PoseFeature> m_features;
    std::unique_ptr<PoseJoin> m_join;
    std::unique_ptr<P2pCleaner> m_cleaner;
    SegmentationTimes m_times;
};

} // namespace trimlab
