#pragma once
/// \file
/// What `trimlab bench` measured: one cell per (scene, frame size, method), plus the run's
/// header (OpenGL, CPU, date, parameters) and the scenes it had to skip. Shared by the
/// text table (bench_table.h) and the JSON file (bench_json.h).

#include "render/frame_times.h"
#include "render/mfr/fragment_method.h"
#include "core/trim/trim_agreement.h"

#include <QSize>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <vector>

namespace trimlab::app {

/// One method on one scene at one size, over the whole camera path.
struct BenchCell {
    QString scene;
    QSize size;
    render::FragmentMethodKind method = render::FragmentMethodKind::KPlusArray;
    /// Set when the method could not render (e.g. out of GPU memory); nothing else is then
    /// meaningful.
    QString error;
    bool outOfMemory = false; ///< the error was a GpuMemoryError (reported, not a failure)
    /// The method cannot render the scene's settings by design (peeling and CSG); `error`
    /// says why. Reported, not a failure.
    bool notApplicable = false;
    render::FrameTimes times; ///< every timed frame of every view
    /// Per view: the same frames pipelined (issued back to back, results read later, as
    /// the viewport does), total wall time / frames — the frame period when CPU and GPU
    /// work overlap; against the GPU time it shows how far they do.
    std::vector<double> pipelinedMs;
    int views = 0;
    int geometryPasses = 0;   ///< most over the views
    int fullscreenPasses = 0; ///< most over the views
    double megabytes = 0.0;   ///< most over the views (method + target + scene)
    bool interlock = false;   ///< the last frame used fragment shader interlock
    bool usesLock = false;    ///< the method has a per-pixel critical section (k⁺-buffer family)
    /// Frame counters of the last frame of each view, summed over the views.
    std::uint64_t fragmentsInSpan = 0;
    std::uint64_t fragmentsStored = 0;
    std::uint64_t fragmentsLost = 0;
    std::uint64_t overflowPixels = 0;
    std::uint64_t unresolvedPixels = 0;
    std::uint64_t spinGiveUps = 0;
    TrimAgreement agreement; ///< summed over the views (counts only)
    double worstViewAgreement = 1.0;
    /// The first view that fails the test criteria and why ("view 3: agreement below ...").
    QString violation;

    [[nodiscard]] bool rendered() const { return error.isEmpty(); }
    [[nodiscard]] bool failed() const
    {
        return !violation.isEmpty() || (!rendered() && !outOfMemory && !notApplicable);
    }
};

struct BenchHeader {
    QString version;
    QString openGl;          ///< GlCapabilities::summary()
    unsigned cpuThreads = 0; ///< std::thread::hardware_concurrency()
    QString date;            ///< ISO 8601, local time with offset
    std::vector<QSize> sizes;
    int views = 0;
    int repeat = 0;
    render::MethodParameters parameters;
    std::vector<render::FragmentMethodKind> methods;
    QStringList scenes; ///< the scenes measured, in order
    QString locks;      ///< --locks: "auto", "spin" or "both"
};

struct BenchSkip {
    QString scene;
    QString reason;
};

struct BenchReport {
    BenchHeader header;
    std::vector<BenchCell> cells;
    std::vector<BenchSkip> skipped;
};

/// The cell of `method` for the same scene and size as `cell`, or nullptr.
[[nodiscard]] const BenchCell* findCell(const BenchReport& report, const BenchCell& cell,
                                        render::FragmentMethodKind method);
/// The cell of the same method, scene and size measured with fragment shader interlock, or
/// nullptr (the spin-lock cells of `--locks both` are compared with it).
[[nodiscard]] const BenchCell* findInterlockCell(const BenchReport& report, const BenchCell& cell);
/// Time of `cell` divided by the time of `base` (both rendered): GPU medians when both
/// are GPU-timed, else wall medians. nullopt when either is missing or did not render.
[[nodiscard]] std::optional<double> timeRatio(const BenchCell& cell, const BenchCell* base);
/// The median over the views of the pipelined frame period (0 without one).
[[nodiscard]] double pipelinedMilliseconds(const BenchCell& cell);
/// The pipelined frame period / the median GPU time: near 1 when the CPU's work hides
/// behind the GPU's. nullopt without a GPU time.
[[nodiscard]] std::optional<double> pipelinedToGpu(const BenchCell& cell);
/// "interlock", "spin-lock" or "none": the critical section the cell was measured with.
[[nodiscard]] QString lockId(const BenchCell& cell);
/// "kplus-array": the method's stable id.
[[nodiscard]] QString methodId(render::FragmentMethodKind method);

} // namespace trimlab::app
