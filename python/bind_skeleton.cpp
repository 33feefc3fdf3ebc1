#include "python/array_convert.h"
#include "python/bindings.h"
#include "python/keyword_parameters.h"
#include "python/python_errors.h"
#include "python/python_progress.h"

#include "core/skeleton/bone_names.h"
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
}

} // namespace trimlab::python
