// The solvers inside the skinning fits, each on its own: affine maps, the per-pose LBS and
// DQS fits (which recover the transforms that made a pose), their solver options, the
// bone-pair normal equations' pattern and chunks, the rigid joint solver and the closest
// rotation, the best convex weights of one vertex, and the float positions of the export.
#include "core/skinning/convex_vertex_weights.h"
#include "core/skinning/proxy_bones.h"
#include "core/skinning/skinning_affine.h"
#include "core/skinning/skinning_dqs_fit.h"
#include "core/skinning/skinning_fit_options.h"
#include "core/skinning/skinning_gltf_parts.h"
#include "core/skinning/skinning_lbs_fit.h"
#include "core/skinning/skinning_normal_equations.h"
#include "core/skinning/skinning_rigid_joint_solver.h"

#include "skinning_fixtures.h"

#include <QtTest>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <random>
#include <set>
#include <stdexcept>

using namespace trimlab;
using namespace trimlab::test;

namespace {

constexpr unsigned kRings = 12, kSides = 8, kBones = 3;

double largestDistance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b)
{
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, glm::length(a[i] - b[i]));
    return worst;
}

std::vector<glm::dvec3> lbsPose(const std::vector<glm::dvec3>& rest, const SkinningWeights& weights,
                                const std::vector<Affine3>& bones)
{
    std::vector<glm::dvec3> posed;
    for (std::size_t j = 0; j < rest.size(); ++j) {
        Affine3 blend{glm::dmat3(0.0), glm::dvec3(0.0)};
        const VertexInfluences& v = weights.vertices[j];
        for (std::uint32_t k = 0; k < v.count; ++k)
            blend = weightedSum(blend, bones[v.bones[k]], v.weights[k]);
        posed.push_back(blend.apply(rest[j]));
    }
    return posed;
}

// All of a vertex's weight on `bone`.
VertexInfluences onlyBone(std::uint32_t bone)
{
    VertexInfluences only;
    only.count = 1;
    only.bones[0] = bone;
    only.weights[0] = 1.0;
    return only;
}

// One bone moves everything: weights of 1 on bone 0.
SkinningWeights oneBone(std::size_t vertices)
{
    SkinningWeights weights;
    weights.boneCount = 1;
    weights.vertices.assign(vertices, onlyBone(0));
    return weights;
}

} // namespace

class TestSkinningParts : public QObject {
    Q_OBJECT

private slots:
    void affineMapsComposeAndBlend()
    {
        const Affine3 scale{glm::dmat3(2.0), glm::dvec3(1, 0, 0)};
        const Affine3 shift{glm::dmat3(1.0), glm::dvec3(0, 3, 0)};
        const glm::dvec3 p(1, 1, 1);
        QCOMPARE(compose(scale, shift).apply(p), scale.apply(shift.apply(p)));
        QCOMPARE(compose(shift, scale).apply(p), glm::dvec3(3, 5, 2));
        const Affine3 half = weightedSum(weightedSum({glm::dmat3(0.0), glm::dvec3(0.0)}, scale, 0.5), shift, 0.5);
        QCOMPARE(half.apply(p), 0.5 * scale.apply(p) + 0.5 * shift.apply(p));
        QVERIFY(Affine3{} == (Affine3{glm::dmat3(1.0), glm::dvec3(0.0)}));
    }

    // A pose made by LBS from affine bones is fitted back to rounding, by the dense and the
    // sparse solver alike; sizes that disagree are refused.
    void lbsFitRecoversTheAffineBones()
    {
        const MeshAnimation tube = tubeRestPose(kRings, kSides);
        const SkinningWeights weights = tubeWeights(tube, kRings, kSides, kBones);
        const std::vector<glm::dvec3> rest = toDoublePositions(tube.poses[0]);
        std::mt19937 random(7);
        std::vector<Affine3> bones;
        for (unsigned b = 0; b < kBones; ++b)
            bones.push_back(randomAffine(random, 0.3, 0.5, 0.05));
        const std::vector<glm::dvec3> target = lbsPose(rest, weights, bones);

        PoseFitOptions dense;
        dense.solver = LinearSolverKind::Dense;
        PoseFitOptions sparse;
        sparse.solver = LinearSolverKind::Sparse;
        const std::vector<Affine3> a = fitAffineBoneTransforms(rest, target, weights, dense);
        const std::vector<Affine3> b = fitAffineBoneTransforms(rest, target, weights, sparse);
        QVERIFY2(largestDistance(lbsPose(rest, weights, a), target) < 1e-8,
                 qPrintable(QString::number(largestDistance(lbsPose(rest, weights, a), target))));
        QVERIFY(largestDistance(lbsPose(rest, weights, b), target) < 1e-8);
        QVERIFY(largestDistance(lbsPose(rest, weights, a), lbsPose(rest, weights, b)) < 1e-8);
        QCOMPARE(PoseFitOptions{}.solver, LinearSolverKind::Automatic);

        std::vector<glm::dvec3> shorter = target;
        shorter.pop_back();
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)fitAffineBoneTransforms(rest, shorter, weights));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, detail::requireFitSizes(3, 3, 2));
        detail::requireFitSizes(3, 3, 3);
    }

    void boneFramesAreWeightedCentroids()
    {
        const std::vector<glm::dvec3> source = {{0, 0, 0}, {2, 0, 0}, {10, 0, 0}};
        SkinningWeights weights;
        weights.boneCount = 2; // bone 1 has no vertices
        weights.vertices.assign(3, onlyBone(0));
        const detail::BoneFrames frames = detail::boneFrames(source, weights);
        QVERIFY(glm::length(frames.centroid[0] - glm::dvec3(4, 0, 0)) < 1e-12);
        QVERIFY(std::abs(frames.radius[0] - std::sqrt((16.0 + 4.0 + 36.0) / 3.0)) < 1e-12);
        QVERIFY(glm::length(frames.centroid[1] - glm::dvec3(4, 0, 0)) < 1e-12);
        QCOMPARE(frames.radius[1], 1.0);
    }

    // A rest-to-pose DQS model's pose is fitted back by the rigid fit; one weighted set of
    // points gives back the rigid motion that moved it.
    void dqsFitRecoversTheRigidBones()
    {
        const MeshAnimation tube = tubeRestPose(kRings, kSides);
        const SkinningModel model = randomModel(SkinningMethod::Dqs, SkinningChain::RestToPose, tube,
                                                tubeWeights(tube, kRings, kSides, kBones), 2, 11);
        const PosePositions target = reconstructPose(model, 1);
        const std::vector<DualQuaternion> fitted = fitRigidBoneTransforms(model.restPositions, target, model.weights);
        QCOMPARE(fitted.size(), std::size_t(kBones));
        SkinningModel refit = model;
        refit.rigid[1] = fitted;
        QVERIFY2(largestDistance(reconstructPose(refit, 1), target) < 1e-7,
                 qPrintable(QString::number(largestDistance(reconstructPose(refit, 1), target))));
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            (void)fitRigidBoneTransforms(model.restPositions, target, model.weights, std::vector<DualQuaternion>(1)));

        const glm::dquat turn = glm::angleAxis(0.7, glm::normalize(glm::dvec3(1, 2, 3)));
        const glm::dvec3 shift(0.5, -1.0, 2.0);
        std::vector<glm::dvec3> source, moved;
        std::vector<double> omega;
        for (int i = 0; i < 6; ++i) {
            source.emplace_back(std::cos(i), std::sin(2.0 * i), 0.3 * i);
            moved.push_back(turn * source.back() + shift);
            omega.push_back(1.0 + i);
        }
        const DualQuaternion motion = fitRigidMotion(source, moved, omega);
        for (std::size_t i = 0; i < source.size(); ++i)
            QVERIFY(glm::length(transformPoint(motion, source[i]) - moved[i]) < 1e-10);
        const DualQuaternion none = fitRigidMotion(source, moved, std::vector<double>(6, 0.0));
        QVERIFY(glm::length(transformPoint(none, source[3]) - source[3]) < 1e-15);
    }

    void closestRotationIsThePolarFactor()
    {
        const glm::dmat3 r = glm::mat3_cast(glm::angleAxis(1.1, glm::normalize(glm::dvec3(0.2, -1, 0.4))));
        const glm::dmat3 back = closestRotation(3.0 * r);
        for (int c = 0; c < 3; ++c)
            QVERIFY(glm::length(back[c] - r[c]) < 1e-12);
        const glm::dmat3 mirror =
            closestRotation(glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)));
        QVERIFY(glm::determinant(mirror) > 0.0); // never a reflection
    }

    // From exact joints nothing changes; from the identity a one-bone target is found.
    void rigidJointSolverMatchesARigidPose()
    {
        const MeshAnimation tube = tubeRestPose(kRings, kSides);
        const std::vector<glm::dvec3> rest = toDoublePositions(tube.poses[0]);
        const SkinningWeights weights = oneBone(rest.size());
        RigidJointPose truth;
        truth.rotation = glm::angleAxis(0.4, glm::normalize(glm::dvec3(0, 1, 1)));
        truth.translation = {1.0, -2.0, 0.5};
        std::vector<glm::dvec3> target;
        for (const glm::dvec3& p : rest)
            target.push_back(truth.rotation * p + truth.translation);
        const RigidJointSolver solver(weights, rest);

        std::vector<RigidJointPose> exact{truth};
        QVERIFY(solver.solve(exact, target) < 1e-18 * double(rest.size()));
        QVERIFY(glm::length(exact[0].translation - truth.translation) < 1e-9);

        std::vector<RigidJointPose> guess(1);
        const double error = solver.solve(guess, target);
        QVERIFY2(error < 1e-12, qPrintable(QString::number(error)));
        QVERIFY(std::abs(std::abs(glm::dot(guess[0].rotation, truth.rotation)) - 1.0) < 1e-9);
        QVERIFY(glm::length(guess[0].translation - truth.translation) < 1e-6);
    }

    // Pairs of bones that share a vertex, each once (lo ≤ hi); chunks cover every vertex
    // once, in order, whatever the count.
    void normalEquationPatternAndChunks()
    {
        const MeshAnimation tube = tubeRestPose(kRings, kSides);
        const SkinningWeights weights = tubeWeights(tube, kRings, kSides, kBones);
        const detail::BonePairPattern pattern = detail::bonePairPattern(weights);
        QCOMPARE(pattern.boneCount, std::size_t(kBones));
        QCOMPARE(pattern.vertexPairs.size(), weights.vertices.size());
        std::set<std::array<std::uint32_t, 2>> pairs(pattern.pairs.begin(), pattern.pairs.end());
        QCOMPARE(pairs.size(), pattern.pairs.size());
        for (const auto& [lo, hi] : pattern.pairs)
            QVERIFY(lo <= hi && hi < kBones);
        for (std::uint32_t b = 0; b < kBones; ++b)
            QVERIFY(pairs.count({b, b}));
        std::set<std::array<std::uint32_t, 2>> shared; // the pairs the vertices name
        for (const VertexInfluences& v : weights.vertices)
            for (std::uint32_t i = 0; i < v.count; ++i)
                for (std::uint32_t k = 0; k < v.count; ++k)
                    shared.insert({std::min(v.bones[i], v.bones[k]), std::max(v.bones[i], v.bones[k])});
        QCOMPARE(pairs, shared);
        for (std::size_t j = 0; j < weights.vertices.size(); ++j) {
            const VertexInfluences& v = weights.vertices[j];
            for (std::uint32_t i = 0; i < v.count; ++i)
                for (std::uint32_t k = 0; k < v.count; ++k) {
                    const auto [lo, hi] = pattern.pairs[pattern.vertexPairs[j][i * kMaxInfluences + k]];
                    QCOMPARE(lo, std::min(v.bones[i], v.bones[k]));
                    QCOMPARE(hi, std::max(v.bones[i], v.bones[k]));
                }
        }

        for (const std::size_t count : {std::size_t(0), std::size_t(1), std::size_t(1000), std::size_t(123457)}) {
            std::size_t next = 0;
            for (std::size_t c = 0; c < detail::chunkCount(count); ++c) {
                const auto [begin, end] = detail::chunkRange(count, c);
                QCOMPARE(begin, next);
                QVERIFY(end >= begin);
                next = end;
            }
            QCOMPARE(next, count);
        }
    }

    // xᵀGx over the simplex: G = diag(1, 4) is least at (0.8, 0.2). The old weights stay
    // unless the new ones are strictly better, and the limit caps the bones used.
    void convexWeightsMinimiseTheGramForm()
    {
        Eigen::MatrixXd gram(2, 2);
        gram << 1.0, 0.0, 0.0, 4.0;
        const VertexInfluences old = onlyBone(3);
        const VertexInfluences best = bestConvexInfluences(gram, {3, 8}, old, 4);
        QCOMPARE(best.count, std::uint32_t(2));
        QCOMPARE(best.bones[0], std::uint32_t(3));
        QVERIFY(std::abs(best.weights[0] - 0.8) < 1e-12);
        QCOMPARE(best.bones[1], std::uint32_t(8));
        QVERIFY(std::abs(best.weights[1] - 0.2) < 1e-12);
        QCOMPARE(bestConvexInfluences(gram, {3, 8}, old, 1), old); // one bone: 3 alone, no better
        const VertexInfluences single = bestConvexInfluences(gram, {3, 8}, onlyBone(8), 1);
        QCOMPARE(single.count, std::uint32_t(1));
        QCOMPARE(single.bones[0], std::uint32_t(3));
    }

    // The tube moved by three rigid bones is cut into exactly the bone count asked for,
    // with a colour per segment.
    void animationsAreSegmentedIntoTheBoneCount()
    {
        MeshAnimation tube = tubeRestPose(kRings, kSides);
        const SkinningModel model = randomModel(SkinningMethod::Dqs, SkinningChain::RestToPose, tube,
                                                tubeWeights(tube, kRings, kSides, kBones), 4, 5);
        for (std::size_t pose = 1; pose < model.poseCount(); ++pose) {
            std::vector<glm::vec3> positions;
            for (const glm::dvec3& p : reconstructPose(model, pose))
                positions.emplace_back(p);
            tube.poses.push_back(std::move(positions));
        }
        for (const std::size_t count : {std::size_t(1), std::size_t(3), std::size_t(5)}) {
            const BoneSegmentation bones = segmentIntoBones(tube, SegmenterSettings{}, count, {});
            QCOMPARE(bones.labeling.count, std::uint32_t(count));
            QCOMPARE(bones.labeling.labels.size(), tube.vertexCount());
            QCOMPARE(bones.colors.size(), count);
            std::vector<int> used(count, 0);
            for (const std::uint32_t label : bones.labeling.labels) {
                QVERIFY(label < count);
                used[label] = 1;
            }
            QCOMPARE(std::count(used.begin(), used.end(), 1), std::ptrdiff_t(count));
        }
    }

    void exportPositionsAreRoundedToFloat()
    {
        const std::vector<glm::vec3> rounded = skinning_gltf::toFloat({{0.1, 1.0 / 3.0, -2.0}});
        QCOMPARE(rounded, (std::vector<glm::vec3>{{0.1f, 1.0f / 3.0f, -2.0f}}));
    }
};

QTEST_APPLESS_MAIN(TestSkinningParts)
#include "tst_skinning_parts.moc"
