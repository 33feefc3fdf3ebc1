#include "python/array_convert.h"
#include "python/bindings.h"
#include "python/keyword_parameters.h"
#include "python/python_errors.h"
#include "python/python_progress.h"

#include "core/skeleton/bone_names.h"
#include "core/skeleton/rig_motion_fit.h"
#include "core/animation/animation_load_parameters.h"
#include "core/skeleton/skeleton_parameters.h"
#include "core/skeleton/skeleton_pipeline.h"

#include <pybind11/stl.h>

namespace trimlab::python {

namespace {

namespace kp = skeleton_parameters;

py::array_t<std::int32_t> intArray(const std::vector<int>& values)
{
    std::vector<std::int32_t> copy(values.begin(), values.end());
    return vectorArray(std::move(copy));
}

py::array_t<std::int32_t> pairsArray(std::vector<std::array<int, 2>> pairs)
{
    py::array_t<std::int32_t> array({py::ssize_t(pairs.size()), py::ssize_t(2)});
    auto out = array.mutable_unchecked<2>();
    for (std::size_t i = 0; i < pairs.size(); ++i)
        for (int c = 0; c < 2; ++c)
            out(py::ssize_t(i), c) = pairs[i][std::size_t(c)];
    return array;
}

// (n, B) dense weights from the sparse top-k influences of each vertex.
py::array_t<double> denseBoneWeights(const BoneWeights& weights, std::size_t boneCount)
{
    py::array_t<double> array({py::ssize_t(weights.vertexCount()), py::ssize_t(boneCount)});
    auto out = array.mutable_unchecked<2>();
    for (py::ssize_t j = 0; j < out.shape(0); ++j)
        for (py::ssize_t b = 0; b < out.shape(1); ++b)
            out(j, b) = 0.0;
    for (std::size_t j = 0; j < weights.vertexCount(); ++j)
        for (std::size_t i = 0; i < weights.bones[j].size(); ++i)
            if (weights.bones[j][i] >= 0)
                out(py::ssize_t(j), py::ssize_t(weights.bones[j][i])) += double(weights.weights[j][i]);
    return array;
}

py::dict resultDict(const SkeletonResult& r)
{
    const SkeletonRig& rig = r.rig;
    std::vector<std::array<int, 2>> bones;
    std::vector<int> boneParents;
    for (const Bone& bone : rig.bones) {
        bones.push_back({bone.head, bone.tail});
        boneParents.push_back(bone.parentBone);
    }
    py::dict d;
    d["nodes"] = pointsArray(std::vector<glm::dvec3>(r.extraction->curve.nodes));
    d["edges"] = pairsArray(r.extraction->curve.edges);
    d["joints"] = pointsArray(std::vector<glm::dvec3>(rig.joints));
    d["parents"] = intArray(rig.parent);
    d["root"] = rig.root;
    d["bones"] = pairsArray(bones);
    d["bone_parents"] = intArray(boneParents);
    d["bone_names"] = boneNames(rig);
    d["vertex_joint"] = intArray(rig.vertexJoint);
    d["weights"] = denseBoneWeights(r.weights->weights(), rig.bones.size());
    d["solver"] = r.extraction->solver;
    d["warnings"] = r.extraction->warnings;
    d["total_ms"] = r.totalMs();
    return d;
}

py::dict skeleton(const py::object& vertices, const py::object& triangles, const py::object& nodes,
                  const py::object& root, const py::object& heatConstant, const py::object& refine,
                  const py::object& maxIterations, const py::object& contractionWeight,
                  const py::object& contractionGrowth, const py::object& maxAttractionWeight,
                  const py::object& progress)
{
    const TriangleMesh mesh = meshFromArrays(vertices, triangles);
    SkeletonPipelineOptions options;
    SkeletonOptions& e = options.extraction;
    ContractionOptions& c = e.contraction;
    e.targetNodes = keywordInt(kp::kTargetNodes, nodes);
    e.rootJoint = keywordInt(kp::kRootJoint, root);
    if (e.rootJoint >= e.targetNodes)
        throw ParameterError("root " + std::to_string(e.rootJoint) + " is not one of the " +
                             std::to_string(e.targetNodes) + " joints (0 to " + std::to_string(e.targetNodes - 1) +
                             ")");
    options.heatConstant = keywordValue(kp::kHeatConstant, heatConstant);
    e.refine = keywordBool(kp::kRefine, refine);
    c.maxIterations = decltype(c.maxIterations)(keywordInt(kp::kMaxIterations, maxIterations));
    c.initialContractionWeight = keywordValue(kp::kInitialContractionWeight, contractionWeight);
    c.contractionGrowth = keywordValue(kp::kContractionGrowth, contractionGrowth);
    c.maxAttractionWeight = keywordValue(kp::kMaxAttractionWeight, maxAttractionWeight);
    const SkeletonResult result = runWithProgress(
        progress, [&](const TaskControl& control) { return runSkeletonPipeline(mesh, options, control); });
    return resultDict(result);
}

// The rig of a skeleton() result (its joints, parents, root, bones, bone_parents and
// vertex_joint); requireValidRig in fitRigToMotion checks that they agree.
SkeletonRig rigFromResult(const py::dict& result)
{
    for (const char* key : {"joints", "parents", "root", "bones", "bone_parents", "weights"})
        if (!result.contains(key))
            throw InputError(std::string("fit_rig: the skeleton has no '") + key + "'; pass what skeleton() returns");
    SkeletonRig rig;
    rig.joints = pointsFromArray(result["joints"], "joints");
    rig.parent = result["parents"].cast<std::vector<int>>();
    rig.root = result["root"].cast<int>();
    const auto bones = result["bones"].cast<std::vector<std::array<int, 2>>>();
    const auto boneParents = result["bone_parents"].cast<std::vector<int>>();
    if (bones.size() != boneParents.size())
        throw InputError("fit_rig: " + std::to_string(bones.size()) + " bones but " +
                         std::to_string(boneParents.size()) + " bone_parents");
    for (std::size_t b = 0; b < bones.size(); ++b)
        rig.bones.push_back({bones[b][0], bones[b][1], boneParents[b]});
    if (result.contains("vertex_joint"))
        rig.vertexJoint = result["vertex_joint"].cast<std::vector<int>>();
    return rig;
}

// Each row of the dense (n, B) weights as the rig's sparse weights, as the bone-heat
// solver keeps them (its largest kBoneInfluences, renormalised).
BoneWeights sparseBoneWeights(py::handle dense, std::size_t boneCount)
{
    const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(dense);
    if (!array || array.ndim() != 2 || std::size_t(array.shape(1)) != boneCount)
        throw InputError("fit_rig: weights must be an (n, " + std::to_string(boneCount) + ") array");
    const auto w = array.unchecked<2>();
    BoneWeights weights;
    weights.bones.resize(std::size_t(w.shape(0)));
    weights.weights.resize(std::size_t(w.shape(0)));
    std::vector<std::pair<double, int>> candidates(boneCount);
    for (py::ssize_t v = 0; v < w.shape(0); ++v) {
        for (std::size_t b = 0; b < boneCount; ++b)
            candidates[b] = {w(v, py::ssize_t(b)), int(b)};
        strongestInfluences(candidates, weights.bones[std::size_t(v)], weights.weights[std::size_t(v)]);
    }
    return weights;
}

py::dict fitRig(const py::dict& result, const py::object& posesObject, const py::object& restPose,
                const py::object& progress)
{
    const SkeletonRig rig = rigFromResult(result);
    const BoneWeights weights = sparseBoneWeights(result["weights"], rig.bones.size());
    const std::vector<std::vector<glm::vec3>> loaded = posesFromArray(posesObject, "poses");
    const std::size_t rest = std::size_t(keywordInt(animation_load_parameters::kRestPose, restPose));
    std::vector<PosePositions> poses;
    for (const std::vector<glm::vec3>& pose : loaded)
        poses.emplace_back(pose.begin(), pose.end());
    if (rest >= poses.size())
        throw ParameterError("rest_pose " + std::to_string(rest) + " is not one of the " +
                             std::to_string(poses.size()) + " poses");
    const RigMotionFit fit = runWithProgress(
        progress, [&](const TaskControl& control) { return fitRigToMotion(rig, weights, poses, rest, {}, control); });
    py::array_t<double> rotations({py::ssize_t(fit.poses.size()), py::ssize_t(rig.bones.size()), py::ssize_t(4)});
    auto q = rotations.mutable_unchecked<3>();
    std::vector<glm::dvec3> translations;
    for (std::size_t p = 0; p < fit.poses.size(); ++p) {
        for (std::size_t b = 0; b < rig.bones.size(); ++b) {
            const glm::dquat r = glm::normalize(fit.poses[p].rotations[b]);
            const double wxyz[4] = {r.w, r.x, r.y, r.z};
            for (int c = 0; c < 4; ++c)
                q(py::ssize_t(p), py::ssize_t(b), c) = wxyz[c];
        }
        translations.push_back(fit.poses[p].rootTranslation);
    }
    py::dict d;
    d["e_rms"] = fit.error.eRms;
    d["e_rms_diagonal"] = fit.error.eRmsDiagonal;
    d["rmse"] = fit.error.rmse;
    d["per_pose"] = vectorArray(std::vector<double>(fit.error.perPose));
    d["per_vertex"] = vectorArray(std::vector<double>(fit.error.perVertex));
    d["rotations"] = rotations;
    d["root_translations"] = pointsArray(std::move(translations));
    d["iterations"] = fit.iterations;
    d["total_ms"] = fit.milliseconds;
    return d;
}

const char* const kFitRigDoc =
    "fit_rig(skeleton, poses, *, rest_pose=0, progress=None) -> dict\n\nHow well a rig reproduces real "
    "motion: the rig of `skeleton` (what skeleton() returned for the rest pose poses[rest_pose]) is posed to "
    "match every pose of `poses` (k, n, 3) by least squares, with its own weights (the largest 4 of each row) "
    "and linear blend skinning; only each bone's rotation about its head and the root's translation are fitted. "
    "Returns e_rms and e_rms_diagonal (as skin() reports its own fit), rmse, per_pose (k,), per_vertex (n,), "
    "rotations (k, bones, 4) as w, x, y, z in each bone's rest-pose axes, root_translations (k, 3), iterations, "
    "total_ms.\n\nRaises InputError for a skeleton or poses that do not agree, ParameterError for a rest pose "
    "out of range; the GIL is released and progress(stage, done, total) called per pose.";

std::string skeletonDoc()
{
    return "skeleton(V, F, *, nodes, root, heat_constant, refine, max_iterations, contraction_weight, "
           "contraction_growth, max_attraction_weight, progress=None) -> dict\n\nThe skeleton of `trimlab "
           "skeleton` (Berenguer & Moreno): the mesh contracted to a curve skeleton, a rig of `nodes` joints with "
           "one root, and bone-heat weights. V: (n, 3), F: (m, 3) of a closed mesh. Returns nodes (N, 3) and edges "
           "(E, 2) of the curve skeleton; joints (J, 3), parents (J,) (-1 at the root), root, bones (J-1, 2) as "
           "(head, tail) joints, bone_parents, bone_names (spine_1, leg_L_2, ...), vertex_joint (n,), weights (n, J-1) "
           "(rows sum to 1), solver, "
           "warnings, total_ms.\n\n" +
           keywordDoc(kp::kTargetNodes) + keywordDoc(kp::kRootJoint) + keywordDoc(kp::kHeatConstant) +
           keywordDoc(kp::kRefine) + keywordDoc(kp::kMaxIterations) + keywordDoc(kp::kInitialContractionWeight) +
           keywordDoc(kp::kContractionGrowth) + keywordDoc(kp::kMaxAttractionWeight) +
           "\nRaises SkeletonInputError for a mesh the extraction refuses, ParameterError, InputError; the GIL is "
           "released and progress(stage, done, total) called between stages.";
}

} // namespace

void bindSkeleton(py::module_& m)
{
    m.def("skeleton", &skeleton, py::arg("V"), py::arg("F"), py::kw_only(), keywordArgument(kp::kTargetNodes),
          keywordArgument(kp::kRootJoint), keywordArgument(kp::kHeatConstant), keywordArgument(kp::kRefine),
          keywordArgument(kp::kMaxIterations), keywordArgument(kp::kInitialContractionWeight),
          keywordArgument(kp::kContractionGrowth), keywordArgument(kp::kMaxAttractionWeight),
          py::arg("progress") = py::none(), skeletonDoc().c_str());
    m.def("fit_rig", &fitRig, py::arg("skeleton"), py::arg("poses"), py::kw_only(),
          keywordArgument(animation_load_parameters::kRestPose), py::arg("progress") = py::none(), kFitRigDoc);
}

} // namespace trimlab::python
