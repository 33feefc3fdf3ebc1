// Fuzz target: GLB chunk framing (glTF 2.0 §4.4) through loadMeshFromMemory. A valid
// one-triangle GLB is rebuilt around the input: its first 20 bytes replace the header's
// declared length and the two chunks' lengths and types (as differences and values), the
// rest is appended as further chunk data. Lengths that run past the data must be refused
// before anything is read past it. Expected outcome for bad data: MeshLoadError.
#include "fuzz_support.h"

#include "core/mesh/mesh_io.h"
#include "core/mesh/mesh_load_error.h"

#include <cstring>

namespace {

constexpr char kJson[] = R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":36}],)"
                         R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
                         R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
                         R"("min":[0,0,0],"max":[1,1,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
                         R"("nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})";

std::uint32_t wordAt(std::string_view bytes, std::size_t i)
{
    std::uint32_t value = 0;
    if (bytes.size() >= 4 * (i + 1))
        std::memcpy(&value, bytes.data() + 4 * i, 4);
    return value;
}

void appendWord(std::string& out, std::uint32_t value)
{
    char bytes[4];
    std::memcpy(bytes, &value, 4);
    out.append(bytes, 4);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view input = trimlab::fuzz::bytesOf(data, size);
    std::string json = kJson;
    json.resize((json.size() + 3) / 4 * 4, ' ');
    const float positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::string bin(reinterpret_cast<const char*>(positions), sizeof positions);
    const std::string_view extra = input.size() > 20 ? input.substr(20) : std::string_view();
    const auto total = std::uint32_t(12 + 8 + json.size() + 8 + bin.size() + extra.size());
    std::string glb = "glTF";
    appendWord(glb, 2);
    appendWord(glb, total + wordAt(input, 0));
    appendWord(glb, std::uint32_t(json.size()) + wordAt(input, 1));
    appendWord(glb, input.size() >= 12 ? wordAt(input, 2) : 0x4E4F534Au);
    glb += json;
    appendWord(glb, std::uint32_t(bin.size()) + wordAt(input, 3));
    appendWord(glb, input.size() >= 20 ? wordAt(input, 4) : 0x004E4942u);
    glb += bin;
    glb += extra;
    trimlab::fuzz::expectTypedErrors<trimlab::MeshLoadError>(
        [&] { (void)trimlab::loadMeshFromMemory(glb, "glb", "fuzz.glb"); });
    return 0;
}
