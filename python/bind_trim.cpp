#include "python/animation_arguments.h"
#include "python/array_convert.h"
#include "python/keyword_parameters.h"
#include "python/bindings.h"
#include "python/python_errors.h"
#include "python/python_progress.h"
#include "python/scene_arguments.h"

#include "core/catalog/pose_scene.h"
#include "core/mesh/mesh_sequence_gltf.h"
#include "core/skinning/skinning_parameters.h"
#include "core/solid/trimmed_animation.h"
#include "core/solid/trimmed_solid.h"
#include "core/trim/clip_set.h"

#include <pybind11/stl.h>

#include <cmath>
#include <string>
#include <vector>

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

// The poses first … last (inclusive) of an animation of `count` poses; last None: the last.
std::pair<std::size_t, std::size_t> poseRange(long long from, const py::object& last, std::size_t count)
{
    const long long to = last.is_none() ? (long long)(count)-1 : py::cast<long long>(last);
    if (from < 0 || to < from || to >= (long long)(count))
        throw InputError("poses " + std::to_string(from) + " to " + std::to_string(to) + ": the animation has " +
                         std::to_string(count) + " poses (0 to " + std::to_string(count - 1) + ")");
    return {std::size_t(from), std::size_t(to)};
}

// Every pose has the first's triangles, so the first pose's refusal is every pose's.
void requirePoseTrimmable(const MeshAnimation& animation, std::size_t pose)
{
    const LoadedScene scene = animationPoseScene(animation, pose, "pose", "pose " + std::to_string(pose));
    if (!scene.trimmable())
        throw NotTrimmableError("pose " + std::to_string(pose) +
                                " has no inside to trim: " + scene.trimUnavailableReason() +
                                " In Python, load_animation(..., close_holes=True) closes the holes of every pose.");
}

py::list trimPoses(const py::object& poses, const py::object& triangles, const std::string& rule,
                   const py::object& clip, long long first, const py::object& last, bool stats,
                   const py::object& progress)
{
    const MeshAnimation animation = animationFromArrays(poses, triangles, py::none());
    const auto [from, to] = poseRange(first, last, animation.poseCount());
    TrimSettings settings = trimSettingsFromArguments(rule, py::none(), py::none(), 1);
    settings.setClipSet(clipSetFromArgument(clip));
    requirePoseTrimmable(animation, from);
    std::vector<TrimmedSolid> solids;
    solids.reserve(to - from + 1);
    runWithProgress(progress, [&](const TaskControl& control) {
        trimAnimationPoses(
            animation, from, to, settings, [&](std::size_t, const TrimmedSolid& solid) { solids.push_back(solid); },
            control);
        return true;
    });
    py::list result;
    for (TrimmedSolid& solid : solids) {
        py::tuple mesh = meshArrays(std::move(solid.mesh));
        result.append(stats ? py::make_tuple(mesh[0], mesh[1], statsDict(solid.stats)) : mesh);
    }
    return result;
}

constexpr const char* kTrimPosesDoc =
    R"doc(trim_poses(poses, F, *, rule="alternating-border", clip=None, first=0, last=None, stats=False, progress=None) -> list

Each pose of an animation trimmed on its own, as `trimlab trim ANIM --poses FIRST:LAST`
writes it: poses first … last (inclusive; last None: the last pose), each the exact
trimmed solid of trim() under the static `rule`, cut by `clip` and capped. poses is
(k, n, 3) float64 (what load_animation returns), F (m, 3) int. Returns one (V, F) per
pose in pose order (with stats=True, (V, F, stats) as trim() gives). The poses are
trimmed as many at a time as there are cores; the solids do not depend on how many.

Dynamic rules, which remember the poses before, have no exact solid and are not offered.
Raises InputError for bad arrays, a rule name or a range outside the animation,
NotTrimmableError when the poses are not closed (load_animation(..., close_holes=True)
closes them), and what the progress callback raises (progress("poses", done, total)
after every pose; the GIL is released).)doc";

// What trim_poses returned (each (V, F) or (V, F, stats)) as the sequence's meshes,
// named by pose from `first` on.
std::vector<SequenceMesh> sequenceFromArguments(const py::handle& solids, long long first)
{
    if (first < 0)
        throw InputError("first must be a pose number >= 0, got " + std::to_string(first));
    if (!py::isinstance<py::sequence>(solids) || py::isinstance<py::str>(solids))
        throw InputError("poses must be a list of (V, F) pairs, as trim_poses returns");
    std::vector<SequenceMesh> meshes;
    for (py::handle item : solids) {
        const auto solid = py::reinterpret_borrow<py::sequence>(item);
        if (!py::isinstance<py::sequence>(item) || (py::len(solid) != 2 && py::len(solid) != 3))
            throw InputError("poses[" + std::to_string(meshes.size()) + "] must be (V, F) or (V, F, stats)");
        const std::size_t pose = std::size_t(first) + meshes.size();
        meshes.push_back({trimmedPoseName(pose), meshFromArrays(py::object(solid[0]), py::object(solid[1]))});
    }
    if (meshes.empty())
        throw InputError("poses is empty: a sequence holds at least one pose");
    return meshes;
}

void savePoses(const std::string& path, const py::object& solids, const py::object& fps, long long first,
               const std::string& comment)
{
    const double rate = keywordValue(skinning_parameters::kExportFps, fps);
    const std::vector<SequenceMesh> meshes = sequenceFromArguments(solids, first);
    try {
        py::gil_scoped_release release;
        saveMeshSequenceGltf(path, meshes, 1.0 / rate, comment);
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    } catch (const std::runtime_error& e) {
        throw MeshSaveError(e.what());
    }
}

std::string savePosesDoc()
{
    return "save_poses(path, poses, *, fps=24, first=0, comment=\"\") -> None\n\nThe trimmed poses (what "
           "trim_poses returns) as one glTF 2.0 file that plays them, as `trimlab trim ANIM --poses A:B -o x.glb` "
           "writes it: a node per pose named pose_0000, pose_0001, ... from `first`, shown in turn by an animation "
           "at `fps` (Blender imports it as objects with scale keys; three.js plays it). path: .glb or .gltf, "
           "written through a temporary file and a rename.\n\n" +
           keywordDoc(skinning_parameters::kExportFps) +
           "\nRaises InputError for bad arrays, an empty list or another extension, MeshSaveError when the file "
           "cannot be written.";
}

} // namespace

void bindTrim(py::module_& m)
{
    m.def("trim", &trim, py::arg("meshes"), py::arg("F") = py::none(), py::kw_only(),
          py::arg("rule") = "alternating-border", py::arg("csg") = py::none(), py::arg("rules") = py::none(),
          py::arg("clip") = py::none(), py::arg("stats") = false, py::arg("progress") = py::none(), kTrimDoc);
    m.def("trim_poses", &trimPoses, py::arg("poses"), py::arg("F"), py::kw_only(),
          py::arg("rule") = "alternating-border", py::arg("clip") = py::none(), py::arg("first") = 0,
          py::arg("last") = py::none(), py::arg("stats") = false, py::arg("progress") = py::none(), kTrimPosesDoc);
    m.def("save_poses", &savePoses, py::arg("path"), py::arg("poses"), py::kw_only(),
          keywordArgument(skinning_parameters::kExportFps), py::arg("first") = 0, py::arg("comment") = "",
          savePosesDoc().c_str());
}

} // namespace trimlab::python
