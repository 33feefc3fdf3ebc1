#pragma once
/// \file
/// The parameters of segmenting a mesh animation that users choose, for `trimlab segment`
/// and the Segmentation panel alike (core/util/parameter_spec.h): feature, reference,
/// clustering and clusters per pose, threads, the cleaning strength h, the mode, and
/// the panel's colouring. Defaults are SegmenterSettings' own (h, mode and colouring:
/// the panel's first start).
///
/// One range where the command line and the panel disagreed: clusters 1–100000 (the
/// panel stopped at 1000, but a dense mesh's finest useful partition has more parts, and
/// a partition never has more clusters than vertices anyway); threads 0–1024 as every
/// verb's (core/util/worker_threads_parameter.h).

#include "core/animation/animation_segmenter.h"
#include "core/util/parameter_spec.h"
#include "core/util/worker_threads_parameter.h"

#include <array>

namespace trimlab {

/// Thesis 3.2: one segmentation for the whole animation (global), built pose by pose as
/// poses arrive (real-time, 3.2.2; the GUI's player streams them), or each pose's
/// partition joined with the next one's (variable, 3.2.3).
enum class SegmentationMode { Global, RealTime, Variable };

} // namespace trimlab

namespace trimlab::segmentation_parameters {

inline constexpr SegmenterSettings kSettings{};

inline constexpr ChoiceValue kFeatures[] = {
    {"rotation", int(FeatureKind::RotationAngle), "Rotation angle"},
    {"velocity", int(FeatureKind::Velocity), "Velocity"},
    {"acceleration", int(FeatureKind::Acceleration), "Acceleration"},
};

inline constexpr ParameterSpec kFeature{
    .id = "feature",
    .flag = "feature",
    .settingsKey = "segmentation/feature",
    .kind = ParameterKind::Choice,
    .defaultValue = int(kSettings.feature.kind),
    .help = "What every pose is partitioned by: the rotation angle of the deformation gradients, or the vertex "
            "velocity or acceleration",
    .choices = kFeatures,
};

inline constexpr ChoiceValue kReferences[] = {
    {"rest", int(ReferenceMode::Rest), "Rest pose"},
    {"previous", int(ReferenceMode::Previous), "Previous pose"},
};

inline constexpr ParameterSpec kReference{
    .id = "reference",
    .flag = "reference",
    .settingsKey = "segmentation/reference",
    .kind = ParameterKind::Choice,
    .defaultValue = int(kSettings.feature.reference),
    .help = "The pose the rotation angles are measured against",
    .choices = kReferences,
};

inline constexpr ChoiceValue kMethods[] = {
    {"region-growing", int(PartitionMethod::RegionGrowing), "Region growing"},
    {"hierarchical", int(PartitionMethod::Hierarchical), "Hierarchical"},
};

inline constexpr ParameterSpec kMethod{
    .id = "method",
    .flag = "method",
    .settingsKey = "segmentation/method",
    .kind = ParameterKind::Choice,
    .defaultValue = int(kSettings.partition.method),
    .help = "How each pose is clustered: region growing is fast, hierarchical splitting gives better clusters",
    .choices = kMethods,
};

inline constexpr ParameterSpec kClusters{
    .id = "clusters",
    .flag = "clusters",
    .settingsKey = "segmentation/clusters",
    .kind = ParameterKind::Integer,
    .min = 1,
    .max = 100000,
    .defaultValue = double(kSettings.partition.clusters),
    .help = "Clusters per pose partition",
    .required = true,
};

inline constexpr ParameterSpec kThreads =
    workerThreadsParameter("segmentation/threads", "Worker threads of the features and partitions");

inline constexpr ParameterSpec kH{
    .id = "h",
    .flag = "h",
    .settingsKey = "segmentation/h",
    .kind = ParameterKind::Real,
    .min = 0.0,
    .max = 1.0,
    .defaultValue = 0.1,
    .help = "Cleaning strength: 0 keeps the over-segmentation, larger values merge more slivers",
    .required = true,
    .decimals = 3,
};

inline constexpr ChoiceValue kModes[] = {
    {"global", int(SegmentationMode::Global), "Global"},
    {"real-time", int(SegmentationMode::RealTime), "Real-time (stream poses)", false},
    {"variable", int(SegmentationMode::Variable), "Variable (per pose)"},
};

inline constexpr ParameterSpec kMode{
    .id = "mode",
    .flag = "mode",
    .settingsKey = "segmentation/mode",
    .kind = ParameterKind::Choice,
    .defaultValue = int(SegmentationMode::Global),
    .help = "Global: one segmentation of the whole animation; variable: also each pose joined with the next; "
            "real-time (the panel's): built pose by pose as the timeline plays",
    .choices = kModes,
};

inline constexpr ParameterSpec kColorBySegment{
    .id = "color-by-segment",
    .flag = "",
    .settingsKey = "segmentation/colorBySegment",
    .kind = ParameterKind::Boolean,
    .min = 0,
    .max = 1,
    .defaultValue = 1,
    .help = "Colour the animation by segment",
};

inline constexpr std::array<const ParameterSpec*, 8> kTable{&kFeature, &kReference, &kMethod, &kClusters,
                                                            &kThreads, &kH,         &kMode,   &kColorBySegment};
static_assert(isWellFormedTable(kTable));

} // namespace trimlab::segmentation_parameters
