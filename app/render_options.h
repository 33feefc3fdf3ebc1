#pragma once
/// \file
/// The options of `trimlab render`, parsed without touching the scene or OpenGL so that
/// bad arguments fail fast with one line.

#include "app/pose_frames.h"
#include "core/animation/pose_sets.h"
#include "app/scene_composition.h"
#include "core/animation/animation_chain.h"
#include "render/mfr/fragment_method.h"
#include "core/trim/trim_settings.h"
#include "core/view/camera.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace trimlab::app {

enum class Backend { KPlus, Reference };

/// How a designed frame (--script, or a .trimlab project) is classified.
enum class Classification { Dynamic, Static };

struct RenderOptions {
    /// Mesh files or "demo:NAME", one scene (loadScenes: object ids count across them), or
    /// one .trimlab project.
    std::vector<std::string> sources;
    /// The one source is a design on its own (isDesignSource), looked at once.
    bool designSource = false;
    /// --object-transform: placements of objects of mesh sources.
    std::vector<ObjectTransformOption> objectTransforms;
    /// Rule (or trimming off), clip planes (--clip, repeated), capping (--cap), CSG
    /// (--csg, --object-rule) and highlights (--highlight).
    TrimSettings trim;
    bool ruleGiven = false;     ///< --rule was on the command line (not the default)
    std::optional<Camera> camera; ///< --camera; otherwise fitted to the scene like the GUI
    int width = 1024;
    int height = 768;
    int k = 16;
    /// --method: the multi-fragment method of the OpenGL backend (an id of fragmentMethods()).
    render::FragmentMethodKind method = render::FragmentMethodKind::KPlusArray;
    int sharedCounters = render::MethodParameters{}.sharedCounters; ///< --shared-counters (S-buffer's S)
    Backend backend = Backend::KPlus;
    unsigned threads = 0;       ///< reference backend; 0 = all cores
    int repeat = 1;             ///< frames rendered; times reported as the median
    QString output;             ///< -o, PNG
    QString depthOutput;        ///< --depth, PFM
    QString idsOutput;          ///< --ids, 16-bit PNG
    QString script;             ///< --script: stroke script replayed on the source mesh
    std::optional<int> frame;   ///< --frame of the replayed script or project; default: the last
    /// --classification: with a script or project, the sets' dynamic rules (the base mesh
    /// classified by --rule) or --rule applied statically to the frame.
    Classification classification = Classification::Dynamic;
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

/// Parses an integer option --`name` from `text` into `out`, which must lie in [lo, hi];
/// returns the one-line error text otherwise.
[[nodiscard]] std::optional<QString> parseIntegerOption(const QString& name, const QString& text, int lo, int hi,
                                                        int& out);

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
