#pragma once
/// \file
/// The options of `trimlab segment`: the flagged rows of segmentation_parameters::kTable
/// (core/animation/segmentation_parameters.h) and of the animation's loading (rest pose,
/// glTF animation and sampling rate), the animation and the output, parsed before the
/// animation is loaded so that bad arguments fail fast with one line.

#include "core/animation/animation_load_parameters.h"
#include "core/animation/animation_loader.h"
#include "core/animation/animation_segmenter.h"
#include "core/animation/segmentation_parameters.h"
#include "core/animation/segmentation_record.h"
#include "core/trim/hole_closing.h"

#include <QString>
#include <QStringList>

#include <array>
#include <string>
#include <variant>

namespace trimlab::app {

/// The rows of `trimlab segment`, in the order of --help.
namespace segment_verb_parameters {

inline constexpr std::array<const ParameterSpec*, 11> kTable{
    &segmentation_parameters::kClusters,
    &segmentation_parameters::kH,
    &segmentation_parameters::kFeature,
    &segmentation_parameters::kMethod,
    &segmentation_parameters::kReference,
    &animation_load_parameters::kRestPose,
    &segmentation_parameters::kMode,
    &animation_load_parameters::kGltfFps,
    &animation_load_parameters::kGltfAnimation,
    &hole_closing_parameters::kCloseHoles,
    &segmentation_parameters::kThreads,
};
static_assert(isWellFormedTable(kTable));

} // namespace segment_verb_parameters

struct SegmentOptions {
    std::string source;
    QString output;
    SegmentationFileFormat format = SegmentationFileFormat::Json;
    SegmenterSettings settings;
    AnimationLoadOptions load;
    double h = 0.0;
    bool variableMode = false;
};

/// Parses the arguments after "segment": the options, or a one-line error; `help`
/// receives the usage text when --help was given (the returned error is then empty).
[[nodiscard]] std::variant<SegmentOptions, QString> parseSegmentOptions(const QStringList& arguments, QString& help);

} // namespace trimlab::app
