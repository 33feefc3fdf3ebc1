#include "core/skeleton/skeleton_json.h"

#include "core/skeleton/rig_validation.h"
#include "core/io/atomic_write.h"
#include "core/io/file_bytes.h"
#include "core/io/json_fields.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

namespace trimlab {

namespace {

using io::fieldPath;
using io::indexPath;
using io::JsonPathError;
using nlohmann::json;

constexpr std::int64_t kMaxIndex = std::numeric_limits<int>::max();

// ---- writing --------------------------------------------------------------------------

json positionsJson(const std::vector<glm::dvec3>& positions)
{
    json array = json::array();
    for (const glm::dvec3& p : positions)
        array.push_back(io::dvec3Json(p));
    return array;
}

json curveJson(const CurveSkeleton& curve)
{
    for (std::size_t e = 0; e < curve.edges.size(); ++e)
        for (const int node : curve.edges[e])
            if (node < 0 || std::size_t(node) >= curve.nodes.size())
                throw std::invalid_argument("skeletonJson: curve skeleton edge " + std::to_string(e) + " names node " +
                                            std::to_string(node) + " of " + std::to_string(curve.nodes.size()));
    json edges = json::array();
    for (const std::array<int, 2>& e : curve.edges)
        edges.push_back(json::array({e[0], e[1]}));
    return json{{"nodes", positionsJson(curve.nodes)}, {"edges", edges}, {"vertex_node", curve.vertexNode}};
}

// ---- reading --------------------------------------------------------------------------

std::vector<glm::dvec3> positionsValue(const json& value, const std::string& path)
{
    io::requireArray(value, path);
    std::vector<glm::dvec3> positions;
    positions.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i)
        positions.push_back(io::dvec3Value(value[i], indexPath(path, i)));
    return positions;
}

std::vector<int> indicesValue(const json& value, std::int64_t low, const std::string& path)
{
    io::requireArray(value, path);
    std::vector<int> indices;
    indices.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i)
        indices.push_back(int(io::integerInRange(value[i], low, kMaxIndex, indexPath(path, i))));
    return indices;
}

std::vector<std::array<int, 2>> pairsValue(const json& value, const std::string& path)
{
    io::requireArray(value, path);
    std::vector<std::array<int, 2>> pairs;
    pairs.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string at = indexPath(path, i);
        const std::vector<int> pair = indicesValue(value[i], 0, at);
        if (pair.size() != 2)
            throw JsonPathError(at, "must be a pair [a, b], not " + std::to_string(pair.size()) + " numbers");
        pairs.push_back({pair[0], pair[1]});
    }
    return pairs;
}

std::vector<Bone> bonesValue(const json& value, const std::string& path)
{
    io::requireArray(value, path);
    std::vector<Bone> bones;
    bones.reserve(value.size());
    for (std::size_t b = 0; b < value.size(); ++b) {
        const std::string at = indexPath(path, b);
        io::requireObject(value[b], at);
        io::rejectUnknownFields(value[b], {"head", "tail", "parent_bone"}, at);
        auto field = [&](std::string_view key, std::int64_t low) {
            return int(io::integerInRange(io::requiredField(value[b], key, at), low, kMaxIndex, fieldPath(at, key)));
        };
        bones.push_back({field("head", 0), field("tail", 0), field("parent_bone", -1)});
    }
    return bones;
}

void checkEdges(const std::vector<std::array<int, 2>>& edges, const SkeletonRig& rig)
{
    if (edges.size() != rig.bones.size())
        throw JsonPathError("edges", std::to_string(edges.size()) + " edges for " + std::to_string(rig.bones.size()) +
                                         " bones (one [head, tail] per bone)");
    for (std::size_t b = 0; b < edges.size(); ++b)
        if (edges[b][0] != rig.bones[b].head || edges[b][1] != rig.bones[b].tail)
            throw JsonPathError(indexPath("edges", b),
                                "is [" + std::to_string(edges[b][0]) + ", " + std::to_string(edges[b][1]) +
                                    "] but bone " + std::to_string(b) + " runs from joint " +
                                    std::to_string(rig.bones[b].head) + " to " + std::to_string(rig.bones[b].tail));
}

CurveSkeleton curveValue(const json& value, const std::string& path)
{
    io::requireObject(value, path);
    io::rejectUnknownFields(value, {"nodes", "edges", "vertex_node"}, path);
    CurveSkeleton curve;
    curve.nodes = positionsValue(io::requiredField(value, "nodes", path), fieldPath(path, "nodes"));
    const std::string edgesPath = fieldPath(path, "edges");
    curve.edges = pairsValue(io::requiredField(value, "edges", path), edgesPath);
    std::vector<std::array<int, 2>> seen;
    for (std::size_t e = 0; e < curve.edges.size(); ++e) {
        const auto [a, b] = curve.edges[e];
        if (!(a < b) || std::size_t(b) >= curve.nodes.size())
            throw JsonPathError(indexPath(edgesPath, e),
                                "must join two existing nodes a < b (of " + std::to_string(curve.nodes.size()) + ")");
        seen.push_back(curve.edges[e]);
    }
    std::sort(seen.begin(), seen.end());
    if (std::adjacent_find(seen.begin(), seen.end()) != seen.end())
        throw JsonPathError(edgesPath, "lists an edge twice");
    const std::string mappingPath = fieldPath(path, "vertex_node");
    curve.vertexNode = indicesValue(io::requiredField(value, "vertex_node", path), 0, mappingPath);
    for (std::size_t v = 0; v < curve.vertexNode.size(); ++v)
        if (std::size_t(curve.vertexNode[v]) >= curve.nodes.size())
            throw JsonPathError(indexPath(mappingPath, v),
                                "node " + std::to_string(curve.vertexNode[v]) + " does not exist");
    return curve;
}

void checkFormat(const json& document)
{
    io::requireObject(document, "");
    const json* format = io::optionalField(document, "format");
    if (!format || !format->is_string() || format->get<std::string>() != kSkeletonFormatName)
        throw JsonPathError("format",
                            "not a TrimLab skeleton (\"format\" is not \"" + std::string(kSkeletonFormatName) + "\")");
    const auto version = io::integerInRange(io::requiredField(document, "version", ""), 1, kMaxIndex, "version");
    if (version > kSkeletonFormatVersion)
        throw JsonPathError("version", "version " + std::to_string(version) + " is newer than this TrimLab (" +
                                           std::to_string(kSkeletonFormatVersion) + "); update TrimLab to open it");
    io::rejectUnknownFields(document,
                            {"format", "version", "generator", "nodes", "root", "parent", "edges", "bones",
                             "vertex_joint", "curve_skeleton"},
                            "");
}

SkeletonDocument readDocument(const json& document)
{
    checkFormat(document);
    SkeletonDocument result;
    SkeletonRig& rig = result.rig;
    rig.joints = positionsValue(io::requiredField(document, "nodes", ""), "nodes");
    rig.root = int(io::integerInRange(io::requiredField(document, "root", ""), 0, kMaxIndex, "root"));
    rig.parent = indicesValue(io::requiredField(document, "parent", ""), -1, "parent");
    rig.bones = bonesValue(io::requiredField(document, "bones", ""), "bones");
    rig.vertexJoint = indicesValue(io::requiredField(document, "vertex_joint", ""), 0, "vertex_joint");
    if (const std::optional<RigProblem> problem = findRigProblem(rig))
        throw JsonPathError(problem->where, problem->reason);
    checkEdges(pairsValue(io::requiredField(document, "edges", ""), "edges"), rig);
    if (const json* curve = io::optionalField(document, "curve_skeleton")) {
        result.curve = curveValue(*curve, "curve_skeleton");
        if (!rig.vertexJoint.empty() && !result.curve->vertexNode.empty() &&
            rig.vertexJoint.size() != result.curve->vertexNode.size())
            throw JsonPathError("curve_skeleton.vertex_node", std::to_string(result.curve->vertexNode.size()) +
                                                                  " entries, but vertex_joint has " +
                                                                  std::to_string(rig.vertexJoint.size()));
    }
    return result;
}

} // namespace

std::string skeletonJson(const SkeletonRig& rig, const CurveSkeleton* curve)
{
    requireValidRig(rig, "skeletonJson");
    json edges = json::array(), bones = json::array();
    for (const Bone& bone : rig.bones) {
        edges.push_back(json::array({bone.head, bone.tail}));
        bones.push_back(json{{"head", bone.head}, {"tail", bone.tail}, {"parent_bone", bone.parentBone}});
    }
    json document = json::object();
    document["format"] = std::string(kSkeletonFormatName);
    document["version"] = kSkeletonFormatVersion;
    document["generator"] = "TrimLab";
    document["nodes"] = positionsJson(rig.joints);
    document["root"] = rig.root;
    document["parent"] = rig.parent;
    document["edges"] = edges;
    document["bones"] = bones;
    document["vertex_joint"] = rig.vertexJoint;
    if (curve)
        document["curve_skeleton"] = curveJson(*curve);
    return document.dump(1) + "\n";
}

void saveSkeletonJson(const std::filesystem::path& path, const SkeletonRig& rig, const CurveSkeleton* curve)
{
    io::writeFileAtomically(path, skeletonJson(rig, curve));
}

SkeletonDocument parseSkeletonJson(std::string_view text, const std::string& displayName)
{
    return io::readJsonDocument<SkeletonFileError>(text, displayName,
                                                   [](const json& document) { return readDocument(document); });
}

SkeletonDocument loadSkeletonJson(const std::filesystem::path& path)
{
    std::string text;
    try {
        text = io::readFileBytes(path, kMaxSkeletonFileBytes);
    } catch (const std::runtime_error& error) {
        throw SkeletonFileError(path.string(), "", error.what());
    }
    return parseSkeletonJson(text, path.string());
}

} // namespace trimlab
