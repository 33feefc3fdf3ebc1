#include "python/animation_arguments.h"
#include "python/array_convert.h"
#include "python/bindings.h"
#include "python/keyword_parameters.h"
#include "python/python_errors.h"
#include "python/python_progress.h"

#include "core/animation/animation_load_parameters.h"
#include "core/animation/animation_loader.h"
#include "core/animation/segmentation_parameters.h"
#include "core/animation/segmentation_run.h"
#include "core/skinning/dual_quaternion.h"
#include "core/skinning/skinning_error.h"
#include "core/skinning/skinning_gltf.h"
#include "core/skinning/skinning_parameters.h"
#include "core/skinning/skinning_pipeline.h"
#include "core/trim/hole_closing.h"

#include <glm/gtc/type_ptr.hpp>
#include <pybind11/stl.h>

namespace trimlab::python {

namespace {

namespace ap = animation_load_parameters;
namespace sp = segmentation_parameters;
namespace kp = skinning_parameters;

py::tuple loadAnimationArrays(const std::string& source, const py::object& restPose, const py::object& closeHoles,
                              const py::object& progress)
{
    AnimationLoadOptions options;
    options.restPose = std::size_t(keywordInt(ap::kRestPose, restPose));
    options.closeHoles = keywordBool(hole_closing_parameters::kCloseHoles, closeHoles);
    HoleClosing closing;
    const MeshAnimation animation = runWithProgress(
        progress, [&](const TaskControl& control) { return loadAnimation(source, options, control, &closing); });
    warnOfCrossingFans(closing);
    std::vector<glm::uvec3> triangles = animation.triangles;
    return py::make_tuple(posesArray(animation.poses), trianglesArray(std::move(triangles)));
}

// ---- segment ----

py::dict segment(const py::object& poses, const py::object& triangles, const py::object& clusters, const py::object& h,
                 const py::object& feature, const py::object& reference, const py::object& method,
                 const py::object& restPose, const py::object& threads, const std::string& name,
                 const py::object& progress)
{
    SegmentationRunOptions run;
    SegmenterSettings& s = run.settings;
    s.partition.clusters = std::size_t(keywordInt(sp::kClusters, clusters));
    const double cleaning = keywordValue(sp::kH, h);
    s.feature.kind = decltype(s.feature.kind)(keywordInt(sp::kFeature, feature));
    s.feature.reference = decltype(s.feature.reference)(keywordInt(sp::kReference, reference));
    s.partition.method = decltype(s.partition.method)(keywordInt(sp::kMethod, method));
    s.threads = unsigned(keywordInt(sp::kThreads, threads));
    run.variable = false;
    MeshAnimation animation = animationFromArrays(poses, triangles, restPose);
    VertexLabeling labels = runWithProgress(progress, [&](const TaskControl& control) {
        try {
            return runSegmentation(std::move(animation), run, control)->segmenter->segment(cleaning);
        } catch (const SegmentationInputError& e) {
            throw SegmentationInputError(name + ": " + e.what());
        }
    });
    py::dict d;
    d["count"] = labels.count;
    d["labels"] = vectorArray(std::move(labels.labels));
    return d;
}

// ---- skin ----

SkinningFitOptions fitOptions(const py::object& method, const py::object& chain, const py::object& influences,
                              const py::object& weightCorrections, const py::object& vertexCorrections,
                              const py::object& threads)
{
    SkinningFitOptions fit;
    fit.chain =
        chain.is_none() ? SkinningChain(int(kp::kChain.defaultValue)) : SkinningChain(keywordInt(kp::kChain, chain));
    chooseSkinningFit(fit, SkinningFitKind(keywordInt(kp::kFit, method)));
    if (fit.fitExported && !chain.is_none())
        throw ParameterError(
            "chain applies to method lbs or dqs; the rigid fit always maps the rest pose to each pose");
    if (!vertexCorrections.is_none())
        fit.vertexCorrections = keywordBool(kp::kVertexCorrections, vertexCorrections);
    if (!weightCorrections.is_none())
        fit.weightCorrections = keywordBool(kp::kWeightCorrections, weightCorrections);
    if (!influences.is_none()) {
        fit.decomposition.maxInfluences = std::size_t(keywordInt(kp::kInfluences, influences));
        if (!usesDecomposition(fit))
            throw ParameterError("influences applies to method rigid (the default) and to method lbs with chain "
                                 "rest-to-pose with corrections; the other fits keep the segmentation's 4");
    }
    fit.threads = unsigned(keywordInt(sp::kThreads, threads));
    return fit;
}

std::shared_ptr<SkinningFit> skin(const py::object& poses, const py::object& triangles, const py::object& bones,
                                  const py::object& method, const py::object& chain, const py::object& influences,
                                  const py::object& weightCorrections, const py::object& vertexCorrections,
                                  const py::object& restPose, const py::object& threads, bool reconstruct,
                                  const std::string& name, const py::object& progress)
{
    const std::size_t boneCount = std::size_t(keywordInt(kp::kBones, bones)); // the command line's order
    SkinningPipelineOptions options;
    options.fit = fitOptions(method, chain, influences, weightCorrections, vertexCorrections, threads);
    options.reconstruct = reconstruct;
    const SkinningBoneSource source = segmentedBones(boneCount, options.fit.threads);
    const MeshAnimation animation = animationFromArrays(poses, triangles, restPose);
    // Python reads the fit and never changes it; pybind11's holder is a pointer to non-const.
    return std::const_pointer_cast<SkinningFit>(runWithProgress(progress, [&](const TaskControl& control) {
        try {
            return runSkinningFit(animation, source, options, control);
        } catch (const SkinningBonesError& e) {
            throw SkinningBonesError(name + ": " + e.what());
        }
    }));
}

py::array_t<double> denseWeights(const SkinningWeights& weights)
{
    py::array_t<double> array({py::ssize_t(weights.vertices.size()), py::ssize_t(weights.boneCount)});
    auto out = array.mutable_unchecked<2>();
    for (py::ssize_t j = 0; j < out.shape(0); ++j)
        for (py::ssize_t b = 0; b < out.shape(1); ++b)
            out(j, b) = 0.0;
    for (std::size_t j = 0; j < weights.vertices.size(); ++j) {
        const VertexInfluences& v = weights.vertices[j];
        for (std::uint32_t i = 0; i < v.count; ++i)
            out(py::ssize_t(j), py::ssize_t(v.bones[i])) += v.weights[i];
    }
    return array;
}

Affine3 poseTransform(const SkinningModel& model, std::size_t pose, std::size_t bone)
{
    return model.method == SkinningMethod::Lbs ? model.affine[pose][bone] : toAffine(model.rigid[pose][bone]);
}

// (P, B, 4, 4) homogeneous matrices, row-major as NumPy reads them: x' = M @ [x, 1].
py::array_t<double> transformsArray(const SkinningModel& model)
{
    const py::ssize_t poses = py::ssize_t(model.poseCount());
    const py::ssize_t bones = py::ssize_t(model.boneCount());
    py::array_t<double> array({poses, bones, py::ssize_t(4), py::ssize_t(4)});
    auto out = array.mutable_unchecked<4>();
    for (py::ssize_t p = 0; p < poses; ++p) {
        for (py::ssize_t b = 0; b < bones; ++b) {
            const Affine3 t = poseTransform(model, std::size_t(p), std::size_t(b));
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c)
                    out(p, b, r, c) = r == 3 ? (c == 3 ? 1.0 : 0.0) : (c == 3 ? t.translation[r] : t.linear[c][r]);
        }
    }
    return array;
}

py::dict errorDict(const SkinningError& e)
{
    py::dict d;
    d["e_rms"] = e.eRms;
    d["e_rms_diagonal"] = e.eRmsDiagonal;
    d["rmse"] = e.rmse;
    d["max_distance"] = e.maxDistance;
    d["per_pose"] = std::vector<double>(e.perPose);
    return d;
}

py::dict saveGltf(const SkinningFit& fit, const std::string& path, const py::object& fps, const py::object& exportKind,
                  const py::object& interpolation)
{
    const double rate = keywordValue(kp::kExportFps, fps);
    SkinExportOptions options;
    options.morphTargets = keywordInt(kp::kExport, exportKind) != 0;
    options.stepInterpolation = keywordInt(kp::kInterpolation, interpolation) != 0;
    options.target = &fit.original;
    ExportedSkin exported;
    SkinningError error;
    {
        py::gil_scoped_release release;
        exported = exportSkinnedGltf(fit.result.model, path, rate, options);
        error = measureSkinningError(fit.original, exported.positions, fit.result.model.restPose);
    }
    py::dict d;
    d["kind"] = std::string(skinExportKindName(exported.kind));
    d["joints"] = exported.joints;
    d["error"] = errorDict(error);
    return d;
}

void bindSkinningFit(py::module_& m)
{
    py::class_<SkinningFit, std::shared_ptr<SkinningFit>>(m, "SkinningFit",
                                                          "A finished skinning fit (what skin() returns).")
        .def_property_readonly("bone_count", [](const SkinningFit& f) { return f.result.model.boneCount(); })
        .def_property_readonly(
            "labels", [](const SkinningFit& f) { return vectorArray(std::vector<std::uint32_t>(f.bones.labels)); },
            "(n,) uint32: the bone (segment) of each vertex the weights start from.")
        .def_property_readonly(
            "weights", [](const SkinningFit& f) { return denseWeights(f.result.model.weights); },
            "(n, B) float64: the weight of bone b at vertex j (rows sum to 1).")
        .def_property_readonly(
            "transforms", [](const SkinningFit& f) { return transformsArray(f.result.model); },
            "(P, B, 4, 4) float64: bone b's transform at pose t, applied to the rest pose (rest-to-pose) or "
            "to the pose before (pose-to-pose), x' = M @ [x, 1].")
        .def_property_readonly(
            "rest_positions",
            [](const SkinningFit& f) { return pointsArray(std::vector<glm::dvec3>(f.result.model.restPositions)); },
            "(n, 3) float64: the rest pose the transforms act on (after vertex corrections).")
        .def_property_readonly(
            "approximation", [](const SkinningFit& f) { return posesArray(f.approximation); },
            "(P, n, 3) float64: every pose as the model reconstructs it (empty unless reconstruct=True).")
        .def_property_readonly(
            "error", [](const SkinningFit& f) { return errorDict(f.result.error); },
            "The fit's error: e_rms (1000·‖A − A'‖_F / √(3nk)), e_rms_diagonal, rmse, max_distance, per_pose.")
        .def("save_gltf", &saveGltf, py::arg("path"), py::kw_only(), keywordArgument(kp::kExportFps),
             keywordArgument(kp::kExport), keywordArgument(kp::kInterpolation),
             ("save_gltf(path, *, fps, export, interpolation) -> dict\n\nWrites the fit as glTF 2.0 (.glb or "
              ".gltf) as `trimlab skin -o` does and returns {kind, joints, error}: the error of the file as a "
              "viewer plays it, against the original poses.\n\n" +
              keywordDoc(kp::kExportFps) + keywordDoc(kp::kExport) + keywordDoc(kp::kInterpolation))
                 .c_str());
}

std::string segmentDoc()
{
    return "segment(poses, F, *, clusters, h, feature, reference, method, rest_pose, threads, name, progress) -> "
           "dict\n\nThe segmentation of a mesh animation (thesis chapter 3), as `trimlab segment` computes it: "
           "every pose partitioned by its feature, the partitions joined and cleaned with h. poses: (k, n, 3) "
           "float64, F: (m, 3) int. Returns {count, labels: (n,) uint32}.\n\n" +
           keywordDoc(sp::kClusters) + keywordDoc(sp::kH) + keywordDoc(sp::kFeature) + keywordDoc(sp::kReference) +
           keywordDoc(sp::kMethod) + keywordDoc(ap::kRestPose) + keywordDoc(sp::kThreads) +
           "    name: prefixes the messages of refusals, as the command line names its file.\n\nRaises "
           "SegmentationInputError (too few poses), ParameterError, InputError; the GIL is released and "
           "progress(stage, done, total) called between poses.";
}

std::string skinDoc()
{
    return "skin(poses, F, *, bones, method, chain, influences, weight_corrections, vertex_corrections, rest_pose, "
           "threads, reconstruct, name, progress) -> SkinningFit\n\nThe skinning fit of `trimlab skin` (thesis "
           "chapter 4): the animation segmented into exactly `bones` parts, one bone each, then the fit and its "
           "corrections. poses: (k, n, 3) float64, F: (m, 3) int. The result has weights (n, B), transforms "
           "(P, B, 4, 4), error, labels, rest_positions, approximation and save_gltf(path).\n\n" +
           keywordDoc(kp::kBones) + keywordDoc(kp::kFit) + keywordDoc(kp::kChain) +
           "        (None: rest-to-pose for rigid, else the default)\n" + keywordDoc(kp::kInfluences) +
           "        (None: the fit's own)\n" + keywordDoc(kp::kWeightCorrections) + keywordDoc(kp::kVertexCorrections) +
           "        (None: on for rigid, off for lbs and dqs, as the command line)\n" + keywordDoc(ap::kRestPose) +
           keywordDoc(sp::kThreads) +
           "    reconstruct: also every pose as the model reconstructs it (approximation).\n"
           "    name: prefixes the messages of refusals, as the command line names its file.\n\nRaises "
           "SkinningBonesError (bones cannot be made: more than the vertices, too few poses), ParameterError, "
           "InputError; the GIL is released and progress(stage, done, total) called between stages.";
}

} // namespace

void bindAnimation(py::module_& m)
{
    m.def("load_animation", &loadAnimationArrays, py::arg("source"), py::kw_only(), keywordArgument(ap::kRestPose),
          keywordArgument(hole_closing_parameters::kCloseHoles), py::arg("progress") = py::none(),
          "load_animation(source, *, rest_pose=0, close_holes=False, progress=None) -> (poses, F)\n\nA mesh "
          "animation: a folder of meshes, a numbered or wildcard pattern (dir/mesh_%04d.obj.gz, dir/mesh_*.obj) or a "
          ".gltf/.glb file. poses: (k, n, 3) float64, F: (m, 3) int32. close_holes: close each hole by a fan in "
          "every pose (as close_holes() does a mesh; a RuntimeWarning names the first pose where a fan crosses the "
          "surface). Raises MeshLoadError naming the file.");
    m.def("segment", &segment, py::arg("poses"), py::arg("F"), py::kw_only(), keywordArgument(sp::kClusters),
          keywordArgument(sp::kH), keywordArgument(sp::kFeature), keywordArgument(sp::kReference),
          keywordArgument(sp::kMethod), keywordArgument(ap::kRestPose), keywordArgument(sp::kThreads),
          py::arg("name") = "animation", py::arg("progress") = py::none(), segmentDoc().c_str());
    bindSkinningFit(m);
    m.def("skin", &skin, py::arg("poses"), py::arg("F"), py::kw_only(), keywordArgument(kp::kBones),
          keywordArgument(kp::kFit), py::arg("chain") = py::none(), py::arg("influences") = py::none(),
          py::arg("weight_corrections") = py::none(), py::arg("vertex_corrections") = py::none(),
          keywordArgument(ap::kRestPose), keywordArgument(sp::kThreads), py::arg("reconstruct") = false,
          py::arg("name") = "animation", py::arg("progress") = py::none(), skinDoc().c_str());
}

} // namespace trimlab::python
