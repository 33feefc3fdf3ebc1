#include "core/timeline/stroke_replay.h"

#include "core/deform/brush_stroke.h"
#include "core/deform/brush_topology.h"
#include "core/util/float_bits.h"
#include "core/io/json_fields.h"

#include <stdexcept>

namespace trimlab::timeline {

using io::fieldPath;
using io::indexPath;

namespace {

// Applies `stroke` to `positions` and returns the frame that records it. The whole array
// is compared afterwards, so the frame lists exactly the vertices whose bits changed
// whatever the brush touched.
Frame applyAndRecord(const deform::BrushTopology& topology, std::vector<glm::vec3>& positions,
                     const deform::Stroke& stroke)
{
    const deform::BrushStroke brush(topology, positions, stroke);
    Frame frame;
    frame.stroke = brush.committed(stroke.drag);
    const std::vector<glm::vec3> before = positions;
    brush.update(stroke.drag, positions);
    for (std::size_t v = 0; v < positions.size(); ++v) {
        if (!sameBits(positions[v], before[v])) {
            frame.vertices.push_back(std::uint32_t(v));
            frame.before.push_back(before[v]);
            frame.after.push_back(positions[v]);
        }
    }
    return frame;
}

} // namespace

Timeline replayStrokeScript(const TriangleMesh& base, const StrokeScript& script, const TaskControl& control,
                            const std::string& sourceName)
{
    const DynamicRule firstRule = script.sets.empty() ? DynamicRule::Confluent : script.sets.front().rule;
    Timeline timeline(base, firstRule);
    const deform::BrushTopology topology(base);
    std::vector<glm::vec3> positions = base.positions;
    const std::size_t total = script.strokeCount();
    std::size_t done = 0;
    control.report("replay", 0, total);
    for (std::size_t s = 0; s < script.sets.size(); ++s) {
        if (s > 0)
            timeline.startSet(script.sets[s].rule);
        const std::vector<deform::Stroke>& strokes = script.sets[s].strokes;
        for (std::size_t i = 0; i < strokes.size(); ++i) {
            control.throwIfCancelled();
            const std::string path = indexPath(fieldPath(indexPath("sets", s), "strokes"), i);
            try {
                timeline.appendFrame(applyAndRecord(topology, positions, strokes[i]));
            } catch (const std::invalid_argument& error) {
                throw StrokeScriptError(sourceName, path, error.what());
            }
            control.report("replay", ++done, total);
        }
    }
    return timeline;
}

} // namespace trimlab::timeline
