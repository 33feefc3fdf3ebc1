#pragma once
/// \file
/// The options of `trimlab skin`: the flagged rows of skinning_parameters::kTable
/// (core/skinning/skinning_parameters.h) and of the animation's loading (rest pose,
/// threads), the corrections list, the animation and the output, parsed before the
/// animation is loaded so that bad arguments fail fast with one line.

#include "core/animation/animation_load_parameters.h"
#include "core/animation/animation_loader.h"
#include "core/skinning/skinning_fitter.h"
#include "core/skinning/skinning_gltf.h"
#include "core/skinning/skinning_parameters.h"
#include "core/trim/hole_closing.h"
#include "core/util/worker_threads_parameter.h"

#include <QString>
#include <QStringList>

#include <array>
#include <string>
#include <variant>

namespace trimlab::app {

/// The rows of `trimlab skin`, in the order of --help.
namespace skin_verb_parameters {

inline constexpr ParameterSpec kThreads = workerThreadsParameter("", "Worker threads");

inline constexpr std::array<const ParameterSpec*, 10> kTable{
    &skinning_parameters::kBones,          &skinning_parameters::kFit,
    &skinning_parameters::kChain,          &skinning_parameters::kInfluences,
    &skinning_parameters::kExportFps,      &skinning_parameters::kExport,
    &skinning_parameters::kInterpolation,  &animation_load_parameters::kRestPose,
    &hole_closing_parameters::kCloseHoles, &kThreads,
};
static_assert(isWellFormedTable(kTable));

} // namespace skin_verb_parameters

struct SkinOptions {
    std::string source;
    QString output;
    std::size_t bones = 0;
    SkinningFitOptions fit;
    SkinExportOptions exported;
    double fps = skinning_parameters::kExportFps.defaultValue;
    AnimationLoadOptions load;
};

/// Parses the arguments after "skin": the options, or a one-line error; `help` receives
/// the usage text when --help was given (the returned error is then empty).
[[nodiscard]] std::variant<SkinOptions, QString> parseSkinOptions(const QStringList& arguments, QString& help);

} // namespace trimlab::app
