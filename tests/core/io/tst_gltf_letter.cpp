// glTF read to the letter of the specification, in the mesh reader and the animation
// loader alike, with every file made in the test: GLB chunks and buffers that run past
// the data they name are refused before they are read; an extension in
// extensionsRequired that TrimLab does not implement is refused (glTF 2.0 §3.12) while
// extensionsUsed alone is ignored; a chain of 200,000 nodes loads in linear time; and a
// small file whose many nodes instance one mesh is refused against the memory budget
// before the instances are allocated.
#include "core/animation/gltf_animation.h"
#include "core/mesh/gltf_scene_size.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/mesh_load_error.h"

#include <tiny_gltf.h>

#include <QElapsedTimer>
#include <QtTest>

#include <cstring>
#include <functional>
#include <string>

using namespace trimlab;

namespace {

// One triangle (36 bytes of positions), two keyframe times (8 bytes) and two
// translations (24 bytes): 68 bytes.
std::string triangleBuffer()
{
    const float values[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 2, 0, 0};
    std::string bytes(reinterpret_cast<const char*>(values), sizeof values);
    return bytes;
}

std::string base64(const std::string& bytes)
{
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t n = std::uint8_t(bytes[i]) << 16;
        if (i + 1 < bytes.size())
            n |= std::uint8_t(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size())
            n |= std::uint8_t(bytes[i + 2]);
        out += kDigits[(n >> 18) & 63];
        out += kDigits[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? kDigits[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kDigits[n & 63] : '=';
    }
    return out;
}

struct Parts {
    std::string extensions; // e.g. "\"extensionsRequired\":[\"X\"],"
    std::string nodes = R"([{"mesh":0}])";
    std::string sceneNodes = "[0]";
    std::string uri;                  // empty: the GLB's BIN chunk
    std::size_t bufferLength = 68;    // the buffer's declared byteLength
    std::size_t positionViewEnd = 36; // where the positions' view ends
    bool animated = false;            // a translation clip on node 0
};

std::string gltfJson(const Parts& p)
{
    std::string json = "{\"asset\":{\"version\":\"2.0\"}," + p.extensions;
    json += "\"buffers\":[{\"byteLength\":" + std::to_string(p.bufferLength) +
            (p.uri.empty() ? "" : ",\"uri\":\"" + p.uri + "\"") + "}],";
    json += "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":" + std::to_string(p.positionViewEnd) +
            "},{\"buffer\":0,\"byteOffset\":36,\"byteLength\":8},{\"buffer\":0,\"byteOffset\":44,\"byteLength\":24}],";
    json += R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},)"
            R"({"bufferView":1,"componentType":5126,"count":2,"type":"SCALAR","min":[0],"max":[1]},)"
            R"({"bufferView":2,"componentType":5126,"count":2,"type":"VEC3"}],)";
    json += R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)";
    if (p.animated)
        json += R"("animations":[{"channels":[{"sampler":0,"target":{"node":0,"path":"translation"}}],)"
                R"("samplers":[{"input":1,"output":2}]}],)";
    json += "\"nodes\":" + p.nodes + ",\"scenes\":[{\"nodes\":" + p.sceneNodes + "}],\"scene\":0}";
    return json;
}

std::string embedded(Parts p)
{
    p.uri = "data:application/octet-stream;base64," + base64(triangleBuffer());
    return gltfJson(p);
}

void appendWord(std::string& out, std::uint32_t value)
{
    char bytes[4];
    std::memcpy(bytes, &value, 4); // GLB is little-endian, as this machine
    out.append(bytes, 4);
}

// A GLB with the JSON of `p` and the buffer as BIN chunk; the chunk lengths written in
// the file are the real ones plus `jsonExtra` and `binExtra`.
std::string glb(const Parts& p, std::uint32_t jsonExtra = 0, std::uint32_t binExtra = 0)
{
    std::string json = gltfJson(p);
    json.resize((json.size() + 3) / 4 * 4, ' ');
    std::string bin = triangleBuffer();
    bin.resize((bin.size() + 3) / 4 * 4, '\0');
    std::string out = "glTF";
    appendWord(out, 2);
    appendWord(out, std::uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    appendWord(out, std::uint32_t(json.size()) + jsonExtra);
    appendWord(out, 0x4E4F534A); // "JSON"
    out += json;
    appendWord(out, std::uint32_t(bin.size()) + binExtra);
    appendWord(out, 0x004E4942); // "BIN\0"
    out += bin;
    return out;
}

std::string loadError(const std::function<void()>& load)
{
    try {
        load();
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

std::string meshError(const std::string& bytes, const char* extension)
{
    return loadError([&] { (void)loadMeshFromMemory(bytes, extension, "hostile.gltf"); });
}

std::string animationError(const std::string& bytes)
{
    return loadError([&] { (void)readGltfAnimation(bytes, "hostile.gltf", "/nonexistent"); });
}

// "a, b, c" for n nodes where node i's only child is i + 1 and the last one shows mesh 0.
std::string chainOfNodes(std::size_t n)
{
    std::string nodes = "[";
    for (std::size_t i = 0; i + 1 < n; ++i)
        nodes += "{\"children\":[" + std::to_string(i + 1) + "]},";
    return nodes + "{\"mesh\":0}]";
}

} // namespace

class TestGltfLetter : public QObject {
    Q_OBJECT
private slots:
    void chunksAndBuffersPastTheirDataAreRefused();
    void requiredExtensionsMustBeImplemented();
    void longNodeChainsLoadInLinearTime();
    void manyInstancesAreRefusedBeforeAllocating();
    void sceneSizesCountEveryInstance();
};

// The walk both readers share and the estimate behind the refusal: each node that shows a
// mesh counts the mesh again; accessors whose declared count cannot fit their view count
// nothing.
void TestGltfLetter::sceneSizesCountEveryInstance()
{
    tinygltf::Model model;
    model.buffers.resize(1);
    model.buffers[0].data.resize(36);
    model.bufferViews.resize(1);
    model.bufferViews[0].byteLength = 36;
    model.accessors.resize(3);
    model.accessors[0].bufferView = 0;
    model.accessors[0].count = 3; // fits
    model.accessors[1].bufferView = 0;
    model.accessors[1].count = 1000000; // cannot fit 36 bytes
    model.accessors[2].bufferView = 0;
    model.accessors[2].count = 3;
    model.meshes.resize(2);
    model.meshes[0].primitives.resize(1);
    model.meshes[0].primitives[0].attributes["POSITION"] = 0;
    model.meshes[0].primitives[0].targets.push_back({{"POSITION", 2}});
    model.meshes[1].primitives.resize(1);
    model.meshes[1].primitives[0].attributes["POSITION"] = 1;
    model.nodes.resize(4);
    model.nodes[0].children = {1, 2, 3};
    model.nodes[1].mesh = 0;
    model.nodes[2].mesh = 0;
    model.nodes[3].mesh = 1;
    QCOMPARE(gltfSceneRoots(model, "t.gltf"), std::vector<int>{0}); // no scenes: the nodes nobody parents
    const std::vector<std::size_t> nodes = gltfSceneNodes(model, {0}, "t.gltf");
    QCOMPARE(nodes, (std::vector<std::size_t>{0, 1, 2, 3}));
    QVERIFY(loadError([&] {
                (void)gltfSceneNodes(model, {0, 9}, "t.gltf");
            }).starts_with("t.gltf: node 9 does not exist (the file has 4 nodes)"));
    QVERIFY(loadError([&] {
                (void)gltfSceneNodes(model, {0, 2}, "t.gltf");
            }).find("node 2 is reached twice") != std::string::npos);
    const GltfSceneSize size = gltfSceneSize(model, nodes);
    QCOMPARE(size.instances, std::uint64_t(3));
    QCOMPARE(size.vertices, std::uint64_t(6));
    QCOMPARE(size.targetVertices, std::uint64_t(6));
    QCOMPARE(size.indices, std::uint64_t(6));
}

void TestGltfLetter::chunksAndBuffersPastTheirDataAreRefused()
{
    Parts plain;
    QCOMPARE(loadMeshFromMemory(glb(plain), "glb", "ok.glb").positions.size(), std::size_t(3));
    struct Case {
        const char* name;
        std::string bytes;
        const char* phrase;
    };
    Parts longBuffer;
    longBuffer.bufferLength = 4096;
    Parts longView;
    longView.positionViewEnd = 400;
    Parts longEmbedded;
    longEmbedded.bufferLength = 4096;
    const Case cases[] = {
        {"JSON chunk past the file", glb(plain, 1000, 0), "chunk"},
        {"BIN chunk past the file", glb(plain, 0, 1000), "chunk"},
        {"buffer longer than the BIN chunk", glb(longBuffer), "byteLength"},
        {"view past its buffer", glb(longView), "buffer"},
        {"embedded buffer shorter than declared", embedded(longEmbedded),
         "Failed to decode 'uri' : data:application/octet-stream;base64,AAAAAAAAAAAAAAAA… (76 more characters)"},
    };
    for (const Case& c : cases) {
        const std::string message =
            c.bytes.starts_with("glTF") ? meshError(c.bytes, "glb") : meshError(c.bytes, "gltf");
        QVERIFY2(!message.empty(), c.name);
        QVERIFY2(message.find(c.phrase) != std::string::npos, (std::string(c.name) + ": " + message).c_str());
    }
}

void TestGltfLetter::requiredExtensionsMustBeImplemented()
{
    Parts variants;
    variants.extensions =
        R"("extensionsUsed":["KHR_materials_variants"],"extensionsRequired":["KHR_materials_variants"],)";
    const std::string message = meshError(embedded(variants), "gltf");
    QVERIFY2(message.find("'KHR_materials_variants', which TrimLab does not implement") != std::string::npos,
             message.c_str());
    variants.animated = true;
    QVERIFY(animationError(embedded(variants)).find("KHR_materials_variants") != std::string::npos);
    // Quantized positions are implemented; an extension only used may be ignored.
    Parts quantized;
    quantized.extensions =
        R"("extensionsUsed":["KHR_mesh_quantization"],"extensionsRequired":["KHR_mesh_quantization"],)";
    QCOMPARE(loadMeshFromMemory(embedded(quantized), "gltf", "q.gltf").positions.size(), std::size_t(3));
    Parts used;
    used.extensions = R"("extensionsUsed":["EXT_something_unknown"],)";
    QCOMPARE(loadMeshFromMemory(embedded(used), "gltf", "u.gltf").positions.size(), std::size_t(3));
}

void TestGltfLetter::longNodeChainsLoadInLinearTime()
{
    // 200,000 nodes: a walk that is quadratic in the depth takes hours here.
    Parts chain;
    chain.nodes = chainOfNodes(200000);
    chain.animated = true;
    const std::string bytes = embedded(chain);
    QElapsedTimer timer;
    timer.start();
    QCOMPARE(loadMeshFromMemory(bytes, "gltf", "chain.gltf").positions.size(), std::size_t(3));
    const MeshAnimation animation = readGltfAnimation(bytes, "chain.gltf", "/nonexistent");
    QCOMPARE(animation.poses.size(), std::size_t(2));
    // The clip moves the chain's root: the mesh at its end moves with it.
    QCOMPARE(animation.poses[1][0], glm::vec3(2, 0, 0));
    qInfo("200,000-node chain: mesh and animation loaded in %lld ms", qint64(timer.elapsed()));
}

void TestGltfLetter::manyInstancesAreRefusedBeforeAllocating()
{
    // 20,000 nodes showing one triangle: 60,000 vertices from a 1 MB file, more than a
    // 1 MiB budget allows.
    Parts instances;
    std::string nodes = "[";
    std::string roots = "[";
    for (int i = 0; i < 20000; ++i) {
        nodes += std::string(i ? "," : "") + "{\"mesh\":0}";
        roots += std::string(i ? "," : "") + std::to_string(i);
    }
    instances.nodes = nodes + "]";
    instances.sceneNodes = roots + "]";
    instances.animated = true;
    const std::string bytes = embedded(instances);
    const QByteArray saved = qgetenv("TRIMLAB_MEMORY_BUDGET");
    qputenv("TRIMLAB_MEMORY_BUDGET", "1M");
    const std::string mesh = meshError(bytes, "gltf");
    const std::string animation = animationError(bytes);
    if (saved.isNull())
        qunsetenv("TRIMLAB_MEMORY_BUDGET");
    else
        qputenv("TRIMLAB_MEMORY_BUDGET", saved);
    QVERIFY2(mesh.find("20000 mesh instances (60000 vertices)") != std::string::npos, mesh.c_str());
    QVERIFY2(mesh.find("memory budget") != std::string::npos, mesh.c_str());
    QVERIFY2(animation.find("20000 mesh instances (60000 vertices") != std::string::npos, animation.c_str());
    // Within the budget the same file loads.
    QCOMPARE(loadMeshFromMemory(bytes, "gltf", "many.gltf").positions.size(), std::size_t(3));
}

QTEST_GUILESS_MAIN(TestGltfLetter)
#include "tst_gltf_letter.moc"
