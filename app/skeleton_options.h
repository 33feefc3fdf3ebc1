#pragma once
/// \file
/// The options of `trimlab skeleton`: every flagged row of skeleton_parameters::kTable
/// (core/skeleton/skeleton_parameters.h: contraction, simplification, refinement,
/// selection, bone-heat constant, Loop subdivision), --close-holes and --rest-pose, then
/// the mesh or animation and the outputs, parsed before the mesh is loaded so that bad
/// arguments fail fast with one line.

#include "core/skeleton/skeleton_extraction.h"
#include "core/skeleton/skeleton_parameters.h"

#include <QString>
#include <QStringList>

#include <cstddef>
#include <string>
#include <variant>

namespace trimlab::app {

struct SkeletonVerbOptions {
    std::string source;
    SkeletonOptions extraction;
    double heatConstant = skeleton_parameters::kHeatConstant.defaultValue; ///< c of the bone-heat weights
    int loopLevels = 0;
    bool closeHoles = false; ///< --close-holes: close the mesh's holes before extraction
    /// An animation (a folder or pattern of poses: isMeshSequenceSource): the rig is made
    /// from this pose and then fitted to every pose (rig_motion_fit.h).
    bool animation = false;
    std::size_t restPose = 0; ///< --rest-pose, animations only
    QString output;           // .glb / .gltf, or empty
    QString json;             // or empty
};

/// Parses the arguments after "skeleton": the options, or a one-line error; `help`
/// receives the usage text when --help was given (the returned error is then empty).
[[nodiscard]] std::variant<SkeletonVerbOptions, QString> parseSkeletonOptions(const QStringList& arguments,
                                                                              QString& help);

} // namespace trimlab::app
