#include "skinning_models.h"

#include "core/animation/sequence_files.h"
#include "core/animation/sequence_loader.h"
#include "core/mesh/triangle_mesh.h"
#include "core/skinning/dual_quaternion.h"
#include "core/skinning/seed_bones.h"
#include "core/skinning/skinning_reconstruction.h"
#include "core/skinning/skinning_weights.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>

namespace trimlab::test {

MeshAnimation selectedPoses(const std::string& source, const std::vector<std::size_t>& keep, std::size_t restPose)
{
    const std::vector<std::filesystem::path> all = sequenceFiles(source);
    std::vector<std::filesystem::path> files;
    for (std::size_t index : keep)
        files.push_back(all.at(index));
    MeshAnimation selected = loadMeshSequence(files);
    selected.restPose = restPose;
    requireWellFormed(selected);
    return selected;
}

namespace {

std::vector<glm::dvec3> segmentCentres(const std::vector<glm::vec3>& positions, const VertexLabeling& labels)
{
    std::vector<glm::dvec3> sum(labels.count, glm::dvec3(0.0));
    std::vector<double> count(labels.count, 0.0);
    for (std::size_t v = 0; v < positions.size(); ++v) {
        sum[labels.labels[v]] += glm::dvec3(positions[v]);
        count[labels.labels[v]] += 1.0;
    }
    for (std::size_t b = 0; b < sum.size(); ++b)
        sum[b] /= std::max(1.0, count[b]);
    return sum;
}

SkinningWeights nearestBoneWeights(const std::vector<glm::vec3>& positions, const std::vector<glm::dvec3>& centres,
                                   std::size_t influences, double diagonal)
{
    SkinningWeights weights;
    weights.boneCount = centres.size();
    for (const glm::vec3& p : positions) {
        std::vector<std::pair<std::uint32_t, double>> candidates;
        for (std::size_t b = 0; b < centres.size(); ++b) {
            const double d = glm::length(glm::dvec3(p) - centres[b]) + 0.05 * diagonal;
            candidates.emplace_back(std::uint32_t(b), 1.0 / (d * d));
        }
        weights.vertices.push_back(sparseInfluences(std::move(candidates), 0, influences));
    }
    return weights;
}

// A rotation by up to 150° about a random axis through `centre`, shifted by up to a tenth
// of the diagonal.
DualQuaternion largeRigid(std::mt19937& random, const glm::dvec3& centre, double diagonal)
{
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const glm::dvec3 axis = glm::normalize(glm::dvec3(u(random), u(random), u(random)) + glm::dvec3(0.0, 0.0, 1e-3));
    const glm::dquat r = glm::angleAxis(glm::radians(150.0) * u(random), axis);
    const glm::dvec3 t = centre - r * centre + 0.1 * diagonal * glm::dvec3(u(random), u(random), u(random));
    return dualQuaternionFromRigid(r, t);
}

DualQuaternion antipodal(const DualQuaternion& q)
{
    return {-q.real, -q.dual};
}

Affine3 largeAffine(std::mt19937& random, const glm::dvec3& centre, double diagonal)
{
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Affine3 a = toAffine(largeRigid(random, centre, diagonal));
    glm::dmat3 strain(1.0);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            strain[c][r] += 0.1 * u(random);
    // About the centre, so the strain does not throw the bone's vertices far away.
    a.translation += a.linear * centre - a.linear * strain * centre;
    a.linear = a.linear * strain;
    return a;
}

} // namespace

SkinningModel chosenTransformModel(const MeshAnimation& animation, std::size_t bones, std::size_t influences,
                                   SkinningMethod method, SkinningChain chain, std::size_t poseCount, unsigned seed)
{
    const std::vector<glm::vec3>& rest = animation.poses[animation.restPose];
    const TriangleMesh restMesh{rest, animation.triangles};
    const double diagonal = 2.0 * computeBounds(restMesh).radius();
    const std::vector<glm::dvec3> centres = segmentCentres(rest, nearestSeedLabels(rest, bones));
    const std::size_t restPose = std::min(animation.restPose, poseCount - 1);
    SkinningModel model =
        identitySkinningModel(method, chain, poseCount, restPose, toDoublePositions(rest),
                              nearestBoneWeights(rest, centres, influences, diagonal), animation.triangles);
    std::mt19937 random(seed);
    for (std::size_t t = 0; t < poseCount; ++t) {
        if (t == restPose)
            continue;
        for (std::size_t b = 0; b < bones; ++b) {
            if (method == SkinningMethod::Lbs)
                model.affine[t][b] = largeAffine(random, centres[b], diagonal);
            else
                model.rigid[t][b] = b % 2 == 1 ? antipodal(largeRigid(random, centres[b], diagonal))
                                               : largeRigid(random, centres[b], diagonal);
        }
    }
    return model;
}

} // namespace trimlab::test
