#include "python/array_convert.h"
#include "python/bindings.h"
#include "python/python_errors.h"
#include "python/python_progress.h"
#include "python/scene_arguments.h"

#include "core/solid/trimmed_solid.h"
#include "core/trim/clip_set.h"

#include <pybind11/stl.h>

#include <cmath>
#include <string>

namespace trimlab::python {

namespace {

py::dict statsDict(const TrimmedSolidStats& s)
{
    py::dict d;
    d["input_triangles"] = s.inputTriangles;
    d["degenerate_triangles"] = s.degenerateTriangles;
    d["refined_faces"] = s.refinedFaces;
    d["cancelled_faces"] = s.cancelledFaces;
    d["components"] = s.components;
    d["kept_faces"] = s.keptFaces;
    d["non_manifold_edges"] = s.nonManifoldEdges;
    d["open_edges"] = s.openEdges;
    d["signed_volume"] = s.signedVolume;
    d["refine_ms"] = s.refineMs;
    d["winding_ms"] = s.windingMs;
    return d;
}

// clip=[(a, b, c, d), ...]: the planes keeping a*x + b*y + c*z + d >= 0, enabled in order.
ClipSet clipSetFromArgument(const py::object& clip)
{
    ClipSet clips;
    if (clip.is_none())
        return clips;
    const auto planes = py::cast<std::vector<std::vector<double>>>(clip);
    if (planes.size() > std::size_t(kMaxClipPlanes))
        throw InputError("clip holds " + std::to_string(planes.size()) + " planes; at most " +
                         std::to_string(kMaxClipPlanes) + " cut one solid");
    for (std::size_t i = 0; i < planes.size(); ++i) {
        const std::vector<double>& p = planes[i];
        if (p.size() != 4)
            throw InputError("clip plane " + std::to_string(i) + " has " + std::to_string(p.size()) +
                             " numbers; give (a, b, c, d) keeping a*x + b*y + c*z + d >= 0");
        const glm::dvec3 normal(p[0], p[1], p[2]);
        if (!std::isfinite(p[3]) || !std::isfinite(normal.x) || !std::isfinite(normal.y) || !std::isfinite(normal.z) ||
            normal == glm::dvec3(0.0))
            throw InputError("clip plane " + std::to_string(i) + " needs a finite, non-zero normal (a, b, c)");
        clips.planes[i] = ClipPlane{true, normal, p[3]};
    }
    return clips;
}

py::tuple trim(const py::object& meshes, const py::object& triangles, const std::string& rule, const py::object& csg,
               const py::object& rules, const py::object& clip, bool stats, const py::object& progress)
{
    const LoadedScene loaded = sceneFromArguments(meshes, triangles);
    TrimSettings settings = trimSettingsFromArguments(rule, csg, rules, loaded.scene.objects.size());
    settings.setClipSet(clipSetFromArgument(clip));
    requireTrimmable(loaded);
    TrimmedSolid solid = runWithProgress(
        progress, [&](const TaskControl& control) { return cutTrimmedSolid(loaded.scene, settings, control); });
    py::tuple mesh = meshArrays(std::move(solid.mesh));
    if (!stats)
        return mesh;
    return py::make_tuple(mesh[0], mesh[1], statsDict(solid.stats));
}

constexpr const char* kTrimDoc =
    R"doc(trim(V, F, *, rule="alternating-border", clip=None, stats=False, progress=None) -> (V, F)
trim([(V0, F0), (V1, F1), ...], *, csg="0 - 1", rules=None, rule=..., ...) -> (V, F)

The trimmed solid as exact geometry, what `trimlab trim` writes: the triangles refined
along all their intersections in exact arithmetic, every cell of space classified by its
winding number under `rule` (or by the CSG expression over the objects, each by its own
rule), and the faces between kept and dropped cells, facing out, as one closed mesh.
Returns V (n, 3) float64 (exact points rounded to float) and F (m, 3) int32; with
stats=True also a dict (faces, open_edges, non_manifold_edges, signed_volume, times).

rule: parity, positive-index, alternating-border, nonzero, negative, w>=K or |w|>=K
(also at-least-K, abs-at-least-K). csg: an expression over object ids with | (union),
& (intersection), - (difference) and parentheses, e.g. "0 | (1 & 2)",
"0 - 1". rules: per-object rules for the CSG, {id: name} or a list (None: `rule`).
clip: up to six planes (a, b, c, d), each keeping a*x + b*y + c*z + d >= 0: the solid
cut by them and closed by caps on them, as `trimlab trim --clip` writes it.

Raises InputError for bad arrays, names or ids, NotTrimmableError when an object is not
closed and consistently oriented, and what the progress callback raises (the GIL is
released; progress(stage, done, total) is called between stages).)doc";

} // namespace

void bindTrim(py::module_& m)
{
    m.def("trim", &trim, py::arg("meshes"), py::arg("F") = py::none(), py::kw_only(),
          py::arg("rule") = "alternating-border", py::arg("csg") = py::none(), py::arg("rules") = py::none(),
          py::arg("clip") = py::none(), py::arg("stats") = false, py::arg("progress") = py::none(), kTrimDoc);
}

} // namespace trimlab::python
