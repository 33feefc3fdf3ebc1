#pragma once
// Synthetic skinned animations with a known exact decomposition, and the libigl elephant
// rig (../shared/data/rigs/libigl-elephant/, layout in ../shared/data/SOURCES.md §2).
#include "core/animation/mesh_animation.h"
#include "core/skinning/skinning_model.h"
#include "core/skinning/skinning_reconstruction.h"
#include "core/skinning/skinning_weights.h"
#include "core/animation/vertex_graph.h"
#include "core/mesh/gzip_input.h"
#include "core/mesh/mesh_io.h"

#include "test_paths.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace trimlab::test {

// An open tube along x: `rings` rings of `sides` vertices, ring r at x = r, radius 1,
// twisted a little per ring so no bone's vertices are coplanar.
inline MeshAnimation tubeRestPose(unsigned rings, unsigned sides)
{
    MeshAnimation a;
    a.poses.emplace_back();
    for (unsigned r = 0; r < rings; ++r)
        for (unsigned s = 0; s < sides; ++s) {
            const double angle = 2.0 * M_PI * (s + 0.3 * r) / sides;
            a.poses[0].emplace_back(float(r), float(std::cos(angle)), float(std::sin(angle)));
        }
    for (unsigned r = 0; r + 1 < rings; ++r)
        for (unsigned s = 0; s < sides; ++s) {
            const unsigned a0 = r * sides + s, a1 = r * sides + (s + 1) % sides;
            const unsigned b0 = a0 + sides, b1 = a1 + sides;
            a.triangles.emplace_back(a0, a1, b1);
            a.triangles.emplace_back(a0, b1, b0);
        }
    return a;
}

// `bones` segments of consecutive rings.
inline VertexLabeling tubeSegments(unsigned rings, unsigned sides, unsigned bones)
{
    VertexLabeling labels;
    labels.count = bones;
    for (unsigned r = 0; r < rings; ++r)
        for (unsigned s = 0; s < sides; ++s)
            labels.labels.push_back(std::min(bones - 1, r * bones / rings));
    return labels;
}

inline SkinningWeights tubeWeights(const MeshAnimation& tube, unsigned rings, unsigned sides, unsigned bones,
                                   double borderWidth = 2.0)
{
    const VertexGraph graph = buildVertexGraph(tube.vertexCount(), tube.triangles);
    return segmentationWeights(graph, toDoublePositions(tube.poses[0]), tubeSegments(rings, sides, bones),
                               {borderWidth});
}

// A rigid motion near the identity: rotation by up to `angle` radians about a random
// axis through a random point of the tube, plus a random shift of up to `shift`.
inline DualQuaternion randomRigid(std::mt19937& random, double angle, double shift)
{
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const glm::dvec3 axis = glm::normalize(glm::dvec3(u(random), u(random), u(random)) + glm::dvec3(0, 0, 1e-3));
    const glm::dquat r = glm::angleAxis(angle * u(random), axis);
    const glm::dvec3 centre(5.0 + 4.0 * u(random), 0.0, 0.0);
    const glm::dvec3 t = centre - r * centre + shift * glm::dvec3(u(random), u(random), u(random));
    return dualQuaternionFromRigid(r, t);
}

// An affine map near the identity: a rigid motion with a little scale and shear.
inline Affine3 randomAffine(std::mt19937& random, double angle, double shift, double strain)
{
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Affine3 a = toAffine(randomRigid(random, angle, shift));
    glm::dmat3 s(1.0);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            s[c][r] += strain * u(random);
    a.linear = a.linear * s;
    return a;
}

// A model with random transforms for every pose but the rest pose.
inline SkinningModel randomModel(SkinningMethod method, SkinningChain chain, const MeshAnimation& rest,
                                 SkinningWeights weights, std::size_t poses, unsigned seed)
{
    SkinningModel model = identitySkinningModel(method, chain, poses, 0, toDoublePositions(rest.poses[0]),
                                                std::move(weights), rest.triangles);
    std::mt19937 random(seed);
    const double scale = chain == SkinningChain::PoseToPose ? 1.0 : 2.0;
    for (std::size_t t = 1; t < poses; ++t)
        for (std::size_t b = 0; b < model.boneCount(); ++b) {
            if (method == SkinningMethod::Lbs)
                model.affine[t][b] = randomAffine(random, 0.15 * scale, 0.2 * scale, 0.05);
            else
                model.rigid[t][b] = randomRigid(random, 0.15 * scale, 0.2 * scale);
        }
    return model;
}

// The animation a model generates (positions rounded to float, as files hold them).
inline MeshAnimation animationOfModel(const SkinningModel& model)
{
    MeshAnimation a;
    a.triangles = model.triangles;
    for (const PosePositions& pose : reconstructPoses(model)) {
        a.poses.emplace_back();
        for (const glm::dvec3& p : pose)
            a.poses.back().emplace_back(p);
    }
    return a;
}

// A tube animation no skinning model reproduces exactly: bending plus a breathing bulge.
inline MeshAnimation bendingTube(unsigned rings, unsigned sides, std::size_t poses)
{
    MeshAnimation a = tubeRestPose(rings, sides);
    const std::vector<glm::vec3> rest = a.poses[0];
    for (std::size_t t = 1; t < poses; ++t) {
        std::vector<glm::vec3> pose = rest;
        const double bend = 0.08 * double(t);
        for (glm::vec3& p : pose) {
            const double angle = bend * p.x / double(rings);
            const double bulge = 1.0 + 0.05 * std::sin(double(t) + p.x);
            const double y = p.y * bulge, z = p.z * bulge;
            p = glm::vec3(float(p.x * std::cos(angle) - y * std::sin(angle)),
                          float(p.x * std::sin(angle) + y * std::cos(angle)), float(z));
        }
        a.poses.push_back(std::move(pose));
    }
    return a;
}

// ---- the libigl elephant rig ----

// A libigl binary DMAT: "0 0\n", "cols rows\n", then rows×cols doubles column-major.
struct Dmat {
    std::size_t rows = 0, cols = 0;
    std::vector<double> values; // column-major
    [[nodiscard]] double at(std::size_t r, std::size_t c) const { return values[c * rows + r]; }
};

inline Dmat readDmatGz(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    const std::string packed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string bytes = gunzip(packed, path.string(), std::size_t(1) << 30);
    std::size_t at = bytes.find('\n');
    const std::size_t second = bytes.find('\n', at + 1);
    std::istringstream header(bytes.substr(at + 1, second - at - 1));
    Dmat m;
    header >> m.cols >> m.rows;
    at = second + 1;
    if (bytes.size() - at != m.rows * m.cols * sizeof(double))
        throw std::runtime_error("unexpected DMAT size in " + path.string());
    m.values.resize(m.rows * m.cols);
    std::memcpy(m.values.data(), bytes.data() + at, bytes.size() - at);
    return m;
}

struct ElephantRig {
    TriangleMesh mesh;
    Dmat weights;   // #V × 24
    Dmat animation; // 288 × 457
    // The transform of bone j in frame f (SOURCES.md: T = col.reshape(3,96).T; rows
    // 4j…4j+3 of T are [Rᵀ; tᵀ], v′ = [v 1]·T_j).
    [[nodiscard]] Affine3 bone(std::size_t frame, std::size_t j) const
    {
        Affine3 a;
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c)
                a.linear[c][r] = animation.at(96 * std::size_t(r) + 4 * j + std::size_t(c), frame);
            a.translation[r] = animation.at(96 * std::size_t(r) + 4 * j + 3, frame);
        }
        return a;
    }
};

inline std::filesystem::path elephantFolder()
{
    return sharedDataPath("rigs/libigl-elephant");
}

inline ElephantRig loadElephantRig()
{
    ElephantRig rig;
    rig.mesh = loadMesh(elephantFolder() / "elephant.obj.gz");
    rig.weights = readDmatGz(elephantFolder() / "elephant-weights.dmat.gz");
    rig.animation = readDmatGz(elephantFolder() / "elephant-anim.dmat.gz");
    return rig;
}

} // namespace trimlab::test
