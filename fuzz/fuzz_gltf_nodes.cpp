// Fuzz target: glTF node graphs, in the mesh reader and the animation loader. The input
// describes the nodes of a one-triangle file: byte 0 and 1 give the node count (at most
// 512), each following byte pair (node, child) adds a child link, bytes with the high bit
// set mark the node they name as showing the mesh; scene roots are the first input byte's
// node and node 0, and a translation clip moves node 0. Cycles, shared children, missing
// nodes, long chains and many instances must end in MeshLoadError or a scene, never in a
// hang, a crash or a quadratic walk.
#include "fuzz_support.h"

#include "core/animation/gltf_animation.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/mesh_load_error.h"

#include <string>
#include <vector>

namespace {

// Positions (36 bytes), two times (8), two translations (24), base64.
constexpr char kBuffer[] =
    "data:application/octet-stream;base64,"
    "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAABAAAAAAAAAAAA=";

std::string graphJson(std::string_view input)
{
    const std::size_t count =
        input.size() < 2 ? 1 : 1 + ((std::size_t(std::uint8_t(input[0])) << 8 | std::uint8_t(input[1])) % 512);
    std::vector<std::vector<int>> children(count);
    std::vector<char> mesh(count, 0);
    for (std::size_t i = 2; i + 1 < input.size(); i += 2) {
        const auto a = std::uint8_t(input[i]);
        const auto b = std::uint8_t(input[i + 1]);
        if (a & 0x80)
            mesh[(a & 0x7f) % count] = 1;
        else
            children[a % count].push_back(int(b) - 8); // some indices are negative or missing
    }
    std::string json = R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":68,"uri":")" + std::string(kBuffer) +
                       R"("}],"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":8},)"
                       R"({"buffer":0,"byteOffset":44,"byteLength":24}],)"
                       R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
                       R"({"bufferView":1,"componentType":5126,"count":2,"type":"SCALAR","min":[0],"max":[1]},)"
                       R"({"bufferView":2,"componentType":5126,"count":2,"type":"VEC3"}],)"
                       R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
                       R"("animations":[{"channels":[{"sampler":0,"target":{"node":0,"path":"translation"}}],)"
                       R"("samplers":[{"input":1,"output":2}]}],"nodes":[)";
    for (std::size_t n = 0; n < count; ++n) {
        json += n ? ",{" : "{";
        json += mesh[n] ? R"("mesh":0,)" : "";
        json += R"("children":[)";
        for (std::size_t c = 0; c < children[n].size(); ++c)
            json += (c ? "," : "") + std::to_string(children[n][c]);
        json += "]}";
    }
    const int root = input.empty() ? 0 : int(std::uint8_t(input[0]) % count);
    json += R"(],"scenes":[{"nodes":[0)" + (root ? "," + std::to_string(root) : std::string()) + R"(]}],"scene":0})";
    return json;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string json = graphJson(trimlab::fuzz::bytesOf(data, size));
    trimlab::fuzz::expectTypedErrors<trimlab::MeshLoadError>(
        [&] { (void)trimlab::loadMeshFromMemory(json, "gltf", "fuzz.gltf"); });
    trimlab::fuzz::expectTypedErrors<trimlab::MeshLoadError>(
        [&] { (void)trimlab::readGltfAnimation(json, "fuzz.gltf", {}); });
    return 0;
}
