#pragma once
/// \file
/// The options of `trimlab bench`, parsed before any scene is loaded or any OpenGL context
/// exists, so that bad arguments fail fast with one line (exit code 2).

#include "app/scene_composition.h"
#include "core/trim/trim_settings.h"
#include "core/util/parameter_spec.h"
#include "core/util/worker_threads_parameter.h"
#include "render/mfr/fragment_method.h"
#include "render/mfr/method_parameter_table.h"

#include <QSize>
#include <QString>
#include <QStringList>

#include <array>
#include <string>
#include <variant>
#include <vector>

namespace trimlab::app {

/// --locks: which per-pixel critical section the k⁺-buffer family is measured with.
enum class BenchLocks {
    Auto,     ///< fragment shader interlock where the driver has it, else the spin-lock
    SpinLock, ///< always the spin-lock
    Both,     ///< as Auto, and where that used interlock, the same method again with the spin-lock
};

/// The numbers and choices of `trimlab bench` (its lists — scenes, sizes, methods — and
/// the composed scene's rule are parsed on their own); kTable in the order of --help.
namespace bench_parameters {

inline constexpr ParameterSpec kRepeat{
    .id = "repeat",
    .flag = "repeat",
    .settingsKey = "",
    .kind = ParameterKind::Integer,
    .min = 1,
    .max = 1000,
    .defaultValue = 5,
    .help = "Timed frames per view, after one untimed warm-up frame per method",
};

inline constexpr ParameterSpec kViews{
    .id = "views",
    .flag = "views",
    .settingsKey = "",
    .kind = ParameterKind::Integer,
    .min = 1,
    .max = 360,
    .defaultValue = 8,
    .help = "Cameras on the orbit around each scene",
};

inline constexpr ParameterSpec kThreads = workerThreadsParameter("", "Worker threads of the CPU reference");

inline constexpr ChoiceValue kLockChoices[] = {
    {"auto", int(BenchLocks::Auto), "Interlock where available"},
    {"spin", int(BenchLocks::SpinLock), "Spin-lock"},
    {"both", int(BenchLocks::Both), "Both"},
};

inline constexpr ParameterSpec kLocks{
    .id = "locks",
    .flag = "locks",
    .settingsKey = "",
    .kind = ParameterKind::Choice,
    .defaultValue = int(BenchLocks::Auto),
    .help = "The k+-buffer family's per-pixel critical section: auto (fragment shader interlock where the driver "
            "has it), spin (always the spin-lock) or both (auto, and each method that used interlock measured "
            "again with the spin-lock)",
    .choices = kLockChoices,
};

inline constexpr std::array<const ParameterSpec*, 6> kTable{
    &render::method_parameters::kK, &render::method_parameters::kSharedCounters, &kRepeat, &kViews, &kThreads, &kLocks};
static_assert(isWellFormedTable(kTable));

} // namespace bench_parameters

struct BenchOptions {
    /// --scenes: catalog names (bench_scenes.h), demo:NAME or mesh files; empty: the catalog.
    QStringList scenes;
    /// --size: one or more frame sizes. Default 1024x768.
    std::vector<QSize> sizes{QSize(1024, 768)};
    /// --methods: the methods to run, in menu order; default every method of this build.
    std::vector<render::FragmentMethodKind> methods;
    /// --k and --shared-counters (other parameters keep their defaults).
    render::MethodParameters parameters;
    int repeat = int(bench_parameters::kRepeat.defaultValue); ///< --repeat: timed frames per view
    int views = int(bench_parameters::kViews.defaultValue);   ///< --views: cameras on the orbit of each scene
    unsigned threads = 0;                                     ///< --threads of the CPU reference; 0 = all cores
    BenchLocks locks = BenchLocks::Auto;
    QString jsonOutput;    ///< --json FILE
    QString dataDirectory; ///< --data DIR: where the catalog's mesh files are
    /// Positional sources: one more scene made of them (object ids across the sources in
    /// order), measured after the --scenes (alone when --scenes is not given), drawn with
    /// `composedTrim` (--rule, --csg, --object-rule) and `objectTransforms`.
    std::vector<std::string> sources;
    TrimSettings composedTrim;
    std::vector<ObjectTransformOption> objectTransforms;
};

/// Parses the arguments after "bench". Returns the options or a one-line error;
/// `helpText` receives the usage text when --help was given (the returned error is then
/// empty).
[[nodiscard]] std::variant<BenchOptions, QString> parseBenchOptions(const QStringList& arguments, QString* helpText);

} // namespace trimlab::app
