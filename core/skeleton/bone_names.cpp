#include "core/skeleton/bone_names.h"

#include "core/skeleton/body_root.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <set>

namespace trimlab {

namespace {

class BoneNamer {
public:
    explicit BoneNamer(const SkeletonRig& rig) : m_rig(rig), m_names(rig.bones.size()), m_outgoing(rig.joints.size())
    {
        for (std::size_t b = 0; b < rig.bones.size(); ++b)
            m_outgoing[static_cast<std::size_t>(rig.bones[b].head)].push_back(static_cast<int>(b));
        m_mass.assign(rig.joints.size(), 0.0);
        for (int j : rig.vertexJoint)
            if (j >= 0 && static_cast<std::size_t>(j) < m_mass.size())
                m_mass[static_cast<std::size_t>(j)] += 1.0;
        // Bones are parents first, so their subtrees add up from the back.
        m_subtree.assign(rig.bones.size(), 0.0);
        for (std::size_t b = rig.bones.size(); b-- > 0;) {
            m_subtree[b] += m_mass[static_cast<std::size_t>(rig.bones[b].tail)];
            if (const int parent = rig.bones[b].parentBone; parent >= 0)
                m_subtree[static_cast<std::size_t>(parent)] += m_subtree[b];
        }
    }

    std::vector<std::string> run()
    {
        if (!m_rig.joints.empty())
            nameAtRoot();
        return m_names;
    }

private:
    // The bones leaving `joint`, heaviest subtree first (ties: lower bone).
    std::vector<int> leaving(int joint) const
    {
        std::vector<int> bones = m_outgoing[static_cast<std::size_t>(joint)];
        std::sort(bones.begin(), bones.end(), [&](int a, int b) {
            const double ma = m_subtree[static_cast<std::size_t>(a)], mb = m_subtree[static_cast<std::size_t>(b)];
            return ma != mb ? ma > mb : a < b;
        });
        return bones;
    }

    // The cosine between the directions of bone `from` and bone `to`.
    double alignment(int from, int to) const
    {
        const auto direction = [&](int b) {
            const Bone& bone = m_rig.bones[static_cast<std::size_t>(b)];
            const glm::dvec3 d =
                m_rig.joints[static_cast<std::size_t>(bone.tail)] - m_rig.joints[static_cast<std::size_t>(bone.head)];
            const double length = glm::length(d);
            return length > 0.0 ? d / length : d;
        };
        return glm::dot(direction(from), direction(to));
    }

    bool likePair(const std::vector<int>& bones, std::size_t first) const
    {
        return bones.size() > first + 1 &&
               m_subtree[static_cast<std::size_t>(bones[first + 1])] >=
                   kLikeLimbs * m_subtree[static_cast<std::size_t>(bones[first])] &&
               m_subtree[static_cast<std::size_t>(bones[first + 1])] > 0.0;
    }

    // "L" for the bone whose tail lies farther along the axis where the two differ most.
    std::pair<std::string, std::string> sides(int a, int b) const
    {
        const glm::dvec3 d = m_rig.joints[static_cast<std::size_t>(m_rig.bones[static_cast<std::size_t>(a)].tail)] -
                             m_rig.joints[static_cast<std::size_t>(m_rig.bones[static_cast<std::size_t>(b)].tail)];
        int axis = 0;
        for (int i = 1; i < 3; ++i)
            if (std::abs(d[i]) > std::abs(d[axis]))
                axis = i;
        return d[axis] >= 0.0 ? std::pair{std::string("L"), std::string("R")}
                              : std::pair{std::string("R"), std::string("L")};
    }

    void nameAtRoot()
    {
        const std::vector<int> bones = leaving(m_rig.root);
        std::size_t next = 0;
        if (bones.empty())
            return;
        follow(bones[next++], "spine", 1);
        if (likePair(bones, next)) {
            const auto [first, second] = sides(bones[next], bones[next + 1]);
            follow(bones[next], "leg_" + first, 1);
            follow(bones[next + 1], "leg_" + second, 1);
            next += 2;
        }
        for (int k = 1; next < bones.size(); ++next, ++k)
            follow(bones[next], k == 1 ? std::string("tail") : "root_branch_" + std::to_string(k - 1), 1);
    }

    // Names `bone` chain_index and walks on along its chain.
    void follow(int bone, const std::string& chain, int index)
    {
        for (;;) {
            m_names[static_cast<std::size_t>(bone)] = unique(chain + "_" + std::to_string(index));
            std::vector<int> bones = leaving(m_rig.bones[static_cast<std::size_t>(bone)].tail);
            if (bones.empty())
                return;
            // The straightest continuation goes on as this chain (the neck above the
            // spine, not an arm); the others keep their order by weight.
            const auto straightest = std::max_element(
                bones.begin(), bones.end(), [&](int a, int b) { return alignment(bone, a) < alignment(bone, b); });
            std::rotate(bones.begin(), straightest, straightest + 1);
            std::size_t next = 1;
            if (chain == "spine" && !m_armsNamed && likePair(bones, 1)) {
                m_armsNamed = true;
                const auto [first, second] = sides(bones[1], bones[2]);
                follow(bones[1], "arm_" + first, 1);
                follow(bones[2], "arm_" + second, 1);
                next = 3;
            }
            for (int k = 1; next < bones.size(); ++next, ++k)
                follow(bones[next], chain + "_" + std::to_string(index) + "_branch_" + std::to_string(k), 1);
            bone = bones.front();
            ++index;
        }
    }

    std::string unique(const std::string& name)
    {
        std::string candidate = name;
        for (int k = 2; !m_used.insert(candidate).second; ++k)
            candidate = name + "_" + std::to_string(k);
        return candidate;
    }

    const SkeletonRig& m_rig;
    std::vector<std::string> m_names;
    std::vector<std::vector<int>> m_outgoing;
    std::vector<double> m_mass, m_subtree;
    std::set<std::string> m_used;
    bool m_armsNamed = false;
};

} // namespace

std::vector<std::string> boneNames(const SkeletonRig& rig)
{
    return BoneNamer(rig).run();
}

} // namespace trimlab
