#pragma once
/// \file
/// The options of `trimlab render`, parsed without touching the scene or OpenGL so that
/// bad arguments fail fast with one line.

#include "app/pose_frames.h"
#include "app/scene_composition.h"
#include "core/animation/animation_chain.h"
#include "core/animation/pose_sets.h"
#include "core/timeline/view_settings.h"
#include "core/trim/inspect_parameters.h"
#include "core/trim/hole_closing.h"
#include "core/trim/trim_settings.h"
#include "core/util/parameter_spec.h"
#include "core/util/worker_threads_parameter.h"
#include "core/view/camera.h"
#include "render/mfr/fragment_method.h"
#include "render/mfr/method_parameter_table.h"

#include <QString>
#include <QStringList>

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace trimlab::app {

/// The rows of `trimlab render` beyond the method's (method_parameter_table.h) and the
/// inspection's (inspect_parameters.h); kTable lists them all, in the order of --help.
namespace render_verb_parameters {

inline constexpr ParameterSpec kRepeat{
    .id = "repeat",
    .flag = "repeat",
    .settingsKey = "",
    .kind = ParameterKind::Integer,
    .min = 1,
    .max = 1000,
    .defaultValue = 1,
    .help = "Render this many times and report the median time (the first frame includes shader JIT)",
};

inline constexpr ParameterSpec kThreads = workerThreadsParameter("", "Worker threads of the reference backend");

inline constexpr ParameterSpec kFrame{
    .id = "frame",
    .flag = "frame",
    .settingsKey = "",
    .kind = ParameterKind::Integer,
    .min = 0,
    .max = 1000000,
    .defaultValue = 0,
    .help = "Frame of the replayed script or of a .trimlab project source (0 = the base mesh)",
    .defaultText = "the last",
};

inline constexpr std::array<const ParameterSpec*, 12> kTable{
    &render::method_parameters::kK,
    &render::method_parameters::kSharedCounters,
    &render::method_parameters::kMemoryBudget,
    &inspect_parameters::kLayerAlpha,
    &inspect_parameters::kGhostAlpha,
    &inspect_parameters::kDensity,
    &inspect_parameters::kFresnel,
    &inspect_parameters::kCapSpacing,
    &kRepeat,
    &kThreads,
    &kFrame,
    &hole_closing_parameters::kCloseHoles,
};
static_assert(isWellFormedTable(kTable));

} // namespace render_verb_parameters

enum class Backend { KPlus, Reference };

/// How a designed frame (--script, or a .trimlab project) is classified.
using Classification = timeline::Classification;

struct RenderOptions {
    /// Mesh files or "demo:NAME", one scene (loadScenes: object ids count across them), or
    /// one .trimlab project.
    std::vector<std::string> sources;
    /// --close-holes: the holes of the mesh sources, or of the animation's poses, are
    /// closed by fans before rendering (core/trim/hole_closing.h).
    bool closeHoles = false;
    /// The one source is a design on its own (isDesignSource), looked at once.
    bool designSource = false;
    /// --object-transform: placements of objects of mesh sources.
    std::vector<ObjectTransformOption> objectTransforms;
    /// Rule (or trimming off), clip planes (--clip, repeated), capping (--cap), CSG
    /// (--csg, --object-rule) and highlights (--highlight).
    TrimSettings trim;
    bool ruleGiven = false;       ///< --rule was on the command line (not the default)
    std::optional<Camera> camera; ///< --camera; otherwise fitted to the scene like the GUI
    int width = 1024;
    int height = 768;
    /// --method: the multi-fragment method of the OpenGL backend (an id of fragmentMethods()).
    render::FragmentMethodKind method = render::FragmentMethodKind::KPlusArray;
    /// --k, --shared-counters and --memory-budget (the others at their defaults).
    render::MethodParameters parameters;
    /// --cap-spacing: trim.cap.spacing is this times the scene's bounding radius.
    double capSpacingFraction = inspect_parameters::kCapSpacing.defaultValue;
    Backend backend = Backend::KPlus;
    unsigned threads = 0;                                           ///< reference backend; 0 = all cores
    int repeat = int(render_verb_parameters::kRepeat.defaultValue); ///< frames rendered; times: the median
    QString output;                                                 ///< -o, PNG
    QString depthOutput;                                            ///< --depth, PFM
    QString idsOutput;                                              ///< --ids, 16-bit PNG
    QString script;           ///< --script: stroke script replayed on the source mesh
    std::optional<int> frame; ///< --frame of the replayed script or project; default: the last
    /// --classification: with a script or project, the sets' dynamic rules (the base mesh
    /// classified by --rule) or --rule applied statically to the frame. Without the flag a
    /// project is classified as it was saved (its view settings), anything else dynamically.
    Classification classification = Classification::Dynamic;
    bool classificationGiven = false; ///< --classification was on the command line
    /// --pose N / --poses A:B: the one source is a mesh animation (a folder, a numbered
    /// pattern or a glTF file) and these poses are rendered under the static rule, one
    /// image each, all with one camera fitted to the poses together.
    std::optional<PoseSelection> poses;
    /// --dynamic-rule with --pose/--poses: the animation is a deformation history and each
    /// pose is classified under this rule against --reference (the rest pose classified
    /// by --rule); unset: --rule applies to each pose alone.
    std::optional<DynamicRule> poseRule;
    PoseReference poseReference = PoseReference::Rest;
    /// --sets A:rule,B:rule with --pose/--poses: the poses after the rest pose grouped into
    /// sets of consecutive poses, each with its rule (core/animation/pose_sets.h); poseRule
    /// then holds the first set's rule, so that every check of a dynamic rule applies.
    std::optional<std::vector<PoseSet>> poseSets;

    /// The source is a design: a stroke script was given, or the one source is a project or
    /// a demo with a history.
    [[nodiscard]] bool designed() const;
};

/// A source that is a design on its own: a .trimlab project or a demo with a history.
[[nodiscard]] bool isDesignSource(const std::string& source);

/// Parses "WxH" (1..16384 each) into `width` and `height`; returns the --size error text
/// on bad input.
[[nodiscard]] std::optional<QString> parseImageSize(const QString& text, int& width, int& height);

/// The ids of every multi-fragment method in this build, in menu order ("kplus-array", ...).
[[nodiscard]] QStringList fragmentMethodIds();

/// Parses the arguments after the verb ("render"). Returns the options or a one-line
/// error message. `helpText` receives the usage text when --help was given (then the
/// returned error is empty).
[[nodiscard]] std::variant<RenderOptions, QString> parseRenderOptions(const QStringList& arguments, QString* helpText);

} // namespace trimlab::app
