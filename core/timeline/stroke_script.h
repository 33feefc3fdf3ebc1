#pragma once
/// \file
/// Stroke scripts: JSON files listing sets of strokes, which the GUI records from a
/// timeline and `trimlab render --script S.json --frame N` replays headless
/// (stroke_replay.h). Schema (docs/project-format.md):
/// `{"format": "trimlab-stroke-script", "version": 1, "sets": [{"rule": "confluent",
///   "strokes": [{"anchor": [x,y,z], "triangle": 123, "drag": [dx,dy,dz], "radius": 0.3,
///   "strength": 1.0, "profile": "smooth",
///   "smoothing": {"iterations": 2, "weights": "uniform", "step": 0.5}}]}]}`.
/// Only "anchor" and "drag" are required in a stroke; omitted fields take BrushSettings'
/// defaults, an omitted rule is "confluent".

#include "core/deform/stroke.h"
#include "core/timeline/timeline.h"
#include "core/trim/dynamic_rule.h"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace trimlab::timeline {

/// The value of the "format" field.
inline constexpr std::string_view kStrokeScriptFormatName = "trimlab-stroke-script";
/// The newest script version this TrimLab reads and the one it writes.
inline constexpr int kStrokeScriptVersion = 1;
/// The largest script file accepted: 256 MiB.
inline constexpr std::size_t kMaxStrokeScriptBytes = std::size_t(256) << 20;

/// One set of concurrent disjoint deformations: its rule and its strokes, in order.
struct ScriptSet {
    DynamicRule rule = DynamicRule::Confluent;
    std::vector<deform::Stroke> strokes;
};

struct StrokeScript {
    std::vector<ScriptSet> sets;
    /// Total number of strokes over all sets.
    [[nodiscard]] std::size_t strokeCount() const;
};

/// A script could not be read. `what()` reads `SOURCE[:LINE:COLUMN]: [PATH: ]REASON`,
/// e.g. `s.json: sets[0].strokes[2].radius: must be > 0` or
/// `s.json:4:17: invalid JSON: syntax error while parsing object - ...`. Line and column
/// are known for JSON syntax errors only (the parsed document keeps no positions).
class StrokeScriptError : public std::runtime_error {
public:
    StrokeScriptError(std::string source, std::string path, std::string reason, std::size_t line = 0,
                      std::size_t column = 0);

    [[nodiscard]] const std::string& source() const noexcept { return m_source; }
    /// JSON path of the offending value ("sets[0].strokes[2].radius"), "" for the document.
    [[nodiscard]] const std::string& path() const noexcept { return m_path; }
    [[nodiscard]] const std::string& reason() const noexcept { return m_reason; }
    /// 1-based, or nullopt when the error is not tied to a position in the text.
    [[nodiscard]] std::optional<std::size_t> line() const noexcept;
    [[nodiscard]] std::optional<std::size_t> column() const noexcept;

private:
    std::string m_source;
    std::string m_path;
    std::string m_reason;
    std::size_t m_line = 0;
    std::size_t m_column = 0;
};

/// Parses script `text`; `sourceName` names it in errors. Throws StrokeScriptError for
/// invalid JSON, a wrong "format", a newer "version", unknown fields (typos), wrong
/// types, unknown names (rule, profile, weights) and invalid values (radius <= 0,
/// strength not finite, step outside (0, 1], iterations outside [0, 10000]). A script
/// needs at least one set; sets may be empty.
[[nodiscard]] StrokeScript parseStrokeScript(std::string_view text, const std::string& sourceName);
/// Reads and parses the script at `path` (named `path.string()` in errors; also
/// StrokeScriptError when it cannot be read or exceeds kMaxStrokeScriptBytes).
[[nodiscard]] StrokeScript loadStrokeScript(const std::filesystem::path& path);

/// The script as JSON text, every field written (doubles with round-trip precision, so
/// parseStrokeScript(strokeScriptJson(s)) reproduces every stroke bit for bit). Throws
/// std::invalid_argument for a stroke that could not be read back (non-finite values,
/// radius <= 0, ...) or a script without sets.
[[nodiscard]] std::string strokeScriptJson(const StrokeScript& script);
/// Writes strokeScriptJson(script) atomically (atomic_write.h); std::runtime_error naming
/// the file on failure.
void writeStrokeScript(const std::filesystem::path& path, const StrokeScript& script);

/// What the GUI records: one script set per timeline set, with the set's rule and the
/// recorded (resolved) strokes of its frames. Replaying it on timeline.base() gives the
/// same frames (stroke_replay.h). Stroke scripts hold brush strokes only: a history with a
/// control-point edit throws std::invalid_argument naming the frame (save a project).
[[nodiscard]] StrokeScript strokeScriptFromTimeline(const Timeline& timeline);

} // namespace trimlab::timeline
