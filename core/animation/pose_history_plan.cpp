#include "core/animation/pose_history_plan.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

/// A pose's chain as its references (the frames before the shown one) and their rules.
struct ChainReferences {
    std::vector<std::size_t> references;
    std::vector<DynamicRule> rules;
};

std::invalid_argument setsError(const std::string& what)
{
    return std::invalid_argument("pose history: " + what);
}

// The sets of one side start next to the rest pose and move away from it.
void requireSide(const std::vector<PoseSet>& sets, std::size_t restPose, bool after, std::size_t pose)
{
    if (sets.empty())
        throw setsError("pose " + std::to_string(pose) + " lies " + (after ? "after" : "before") + " the rest pose " +
                        std::to_string(restPose) + ", where no set covers it");
    if (sets.front().firstPose != (after ? restPose + 1 : restPose - 1))
        throw setsError("the first set " + std::string(after ? "after" : "before") + " the rest pose must start at " +
                        "pose " + std::to_string(after ? restPose + 1 : restPose - 1));
    for (std::size_t i = 1; i < sets.size(); ++i)
        if (after ? sets[i].firstPose <= sets[i - 1].firstPose : sets[i].firstPose >= sets[i - 1].firstPose)
            throw setsError("the sets must start at poses that move away from the rest pose");
}

ChainReferences chainReferences(const PoseHistorySets& sets, std::size_t pose)
{
    ChainReferences chain;
    if (pose == sets.restPose)
        return chain;
    const bool after = pose > sets.restPose;
    const std::vector<PoseSet>& side = after ? sets.after : sets.before;
    requireSide(side, sets.restPose, after, pose);
    for (const PoseSet& set : side) {
        if (after ? set.firstPose > pose : set.firstPose < pose)
            break;
        chain.references.push_back(after ? set.firstPose - 1 : set.firstPose + 1);
        chain.rules.push_back(set.rule);
    }
    return chain;
}

// The levels of `chain` (which shows `pose`) from its level `first` on.
std::vector<PoseHistoryLevel> levelsFrom(const ChainReferences& chain, std::size_t pose, std::size_t first)
{
    std::vector<PoseHistoryLevel> levels;
    const std::vector<std::size_t>& refs = chain.references;
    for (std::size_t i = first; i < refs.size(); ++i)
        levels.push_back({refs[i], i + 1 < refs.size() ? refs[i + 1] : pose, chain.rules[i]});
    return levels;
}

bool sameSide(std::size_t restPose, std::size_t a, std::size_t b)
{
    return (a > restPose) == (b > restPose) && a != restPose && b != restPose;
}

} // namespace

PoseHistorySets referenceHistory(std::size_t restPose, std::size_t poseCount, PoseReference reference, DynamicRule rule)
{
    PoseHistorySets sets;
    sets.restPose = restPose;
    sets.after = referenceSets(restPose, poseCount, reference, rule);
    for (std::size_t first = restPose; first > 0; --first) {
        sets.before.push_back({first - 1, rule});
        if (reference == PoseReference::Rest)
            break;
    }
    return sets;
}

std::vector<PoseHistoryLevel> poseHistoryLevels(const PoseHistorySets& sets, std::size_t pose)
{
    return levelsFrom(chainReferences(sets, pose), pose, 0);
}

PoseHistoryStep planPoseHistory(const PoseHistorySets& sets, std::optional<std::size_t> shown, std::size_t wanted)
{
    const ChainReferences target = chainReferences(sets, wanted);
    if (!shown || !sameSide(sets.restPose, *shown, wanted))
        return {PoseHistoryStep::Kind::New, levelsFrom(target, wanted, 0)};
    const ChainReferences held = chainReferences(sets, *shown);
    const std::vector<std::size_t>& have = held.references;
    const std::vector<std::size_t>& want = target.references;
    if (have == want)
        return {PoseHistoryStep::Kind::ReplaceShown, levelsFrom(target, wanted, want.size() - 1)};
    if (have.size() < want.size() && std::equal(have.begin(), have.end(), want.begin()) && want[have.size()] == *shown)
        return {PoseHistoryStep::Kind::Append, levelsFrom(target, wanted, have.size())};
    return {PoseHistoryStep::Kind::New, levelsFrom(target, wanted, 0)};
}

} // namespace trimlab
