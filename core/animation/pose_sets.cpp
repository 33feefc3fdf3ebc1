#include "core/animation/pose_sets.h"

#include <charconv>
#include <stdexcept>

namespace trimlab {

std::optional<std::vector<PoseSet>> parsePoseSets(std::string_view text, std::string& error)
{
    std::vector<PoseSet> sets;
    while (!text.empty()) {
        const std::size_t comma = text.find(',');
        const std::string_view item = text.substr(0, comma);
        text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
        const std::size_t colon = item.find(':');
        if (colon == std::string_view::npos) {
            error = "'" + std::string(item) + "' is not FIRST_POSE:RULE (e.g. 1:confluent)";
            return std::nullopt;
        }
        PoseSet set;
        const std::string_view number = item.substr(0, colon);
        const auto [end, failure] = std::from_chars(number.data(), number.data() + number.size(), set.firstPose);
        if (failure != std::errc{} || end != number.data() + number.size() || number.empty()) {
            error = "'" + std::string(number) + "' in '" + std::string(item) + "' is not a pose number";
            return std::nullopt;
        }
        const std::optional<DynamicRule> rule = parseDynamicRule(item.substr(colon + 1));
        if (!rule) {
            error = "unknown rule '" + std::string(item.substr(colon + 1)) +
                    "' (use additive, subtractive, intersection, confluent or homogeneous-confluent)";
            return std::nullopt;
        }
        set.rule = *rule;
        sets.push_back(set);
    }
    if (sets.empty())
        error = "no sets given (e.g. 1:confluent,40:additive)";
    return sets.empty() ? std::nullopt : std::optional(sets);
}

std::string poseSetsText(const std::vector<PoseSet>& sets)
{
    std::string text;
    for (const PoseSet& set : sets)
        text +=
            (text.empty() ? "" : ",") + std::to_string(set.firstPose) + ":" + std::string(dynamicRuleName(set.rule));
    return text;
}

void requireValidPoseSets(const std::vector<PoseSet>& sets, std::size_t restPose, std::size_t poseCount)
{
    if (sets.empty())
        throw std::invalid_argument("no pose sets given");
    if (sets.front().firstPose != restPose + 1)
        throw std::invalid_argument("the first set must start right after the rest pose " + std::to_string(restPose) +
                                    ", at pose " + std::to_string(restPose + 1) + ", not " +
                                    std::to_string(sets.front().firstPose));
    for (std::size_t i = 0; i < sets.size(); ++i) {
        if (sets[i].firstPose >= poseCount)
            throw std::invalid_argument("set " + std::to_string(i + 1) + " starts at pose " +
                                        std::to_string(sets[i].firstPose) + ", but the animation has poses 0 to " +
                                        std::to_string(poseCount - 1));
        if (i > 0 && sets[i].firstPose <= sets[i - 1].firstPose)
            throw std::invalid_argument(
                "the sets must start at increasing poses: " + std::to_string(sets[i].firstPose) + " follows " +
                std::to_string(sets[i - 1].firstPose));
    }
}

std::size_t setOfPose(const std::vector<PoseSet>& sets, std::size_t pose)
{
    std::size_t index = 0;
    while (index + 1 < sets.size() && sets[index + 1].firstPose <= pose)
        ++index;
    return index;
}

std::vector<PoseSet> referenceSets(std::size_t restPose, std::size_t poseCount, PoseReference reference,
                                   DynamicRule rule)
{
    std::vector<PoseSet> sets;
    for (std::size_t first = restPose + 1; first < poseCount; ++first) {
        sets.push_back({first, rule});
        if (reference == PoseReference::Rest)
            break;
    }
    return sets;
}

DynamicChainLevel poseSetShownLevel(const MeshAnimation& animation, std::size_t pose, const std::vector<PoseSet>& sets)
{
    const PoseSet& set = sets[setOfPose(sets, pose)];
    return {makeDynamicFrameScene(animation.triangles, animation.poses[set.firstPose - 1], animation.poses[pose]),
            set.rule};
}

std::optional<DynamicChain> poseSetChain(const MeshAnimation& animation, std::size_t pose,
                                         const std::vector<PoseSet>& sets, StaticRule baseRule)
{
    if (pose >= animation.poseCount())
        throw std::out_of_range("pose " + std::to_string(pose) + " does not exist; the animation has " +
                                std::to_string(animation.poseCount()) + " poses");
    requireValidPoseSets(sets, animation.restPose, animation.poseCount());
    if (pose == animation.restPose)
        return std::nullopt;
    if (pose < animation.restPose)
        throw std::invalid_argument("pose " + std::to_string(pose) + " comes before the rest pose " +
                                    std::to_string(animation.restPose) + ", which the sets start after");
    const std::size_t last = setOfPose(sets, pose);
    std::vector<std::vector<glm::vec3>> frames;
    std::vector<DynamicRule> rules;
    for (std::size_t i = 0; i <= last; ++i) {
        frames.push_back(animation.poses[sets[i].firstPose - 1]); // the set's reference
        rules.push_back(sets[i].rule);
    }
    frames.push_back(animation.poses[pose]);
    return makeDynamicChain(animation.triangles, frames, rules, baseRule);
}

} // namespace trimlab
