// The CPU-side jobs that can grow without bound estimate their memory first and refuse
// beyond the budget (core/util/memory_budget.h) with a message that says how much, against
// what, and what to change: the CPU reference render, Loop subdivision, a surface's
// tessellation (as a version-2 project loads it), and loading an animation. The budget is
// set small through TRIMLAB_MEMORY_BUDGET here; under the default (half the machine's
// memory) the same small jobs run. Decompression checks each growth of its output against
// the budget too.
#include "core/animation/animation_loader.h"
#include "core/catalog/demo_scenes.h"
#include "core/mesh/loop_subdivision.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/mesh_load_error.h"
#include "core/surface/editable_surface.h"
#include "core/surface/subdivision_cages.h"
#include "core/surface/surface_definition.h"
#include "core/trim/reference_renderer.h"
#include "core/util/memory_budget.h"
#include "core/view/camera.h"

#include "test_paths.h"

#include <QtTest>

#include <zlib.h>

#include <functional>

using namespace trimlab;

namespace {

/// The MemoryBudgetError `job` threw, or "" when it threw none.
std::string budgetError(const std::function<void()>& job)
{
    try {
        job();
    } catch (const MemoryBudgetError& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("another error: ") + e.what();
    }
    return {};
}

Scene sphere()
{
    return *makeDemoScene("sphere");
}

/// The four jobs, each sized to need a few MiB.
struct Job {
    const char* name;
    std::function<void()> run;
    const char* message; ///< what its refusal must say
};

std::vector<Job> jobs()
{
    return {
        {"CPU reference",
         [] {
             const Scene scene = sphere();
             const ReferenceRenderer reference(scene);
             (void)reference.render(fitCamera(scene.worldBounds(), 1.0), 400, 400, TrimSettings{}, 1);
         },
         "the CPU reference at 400x400 needs about "},
        {"Loop subdivision", [] { (void)loopSubdivide(sphere().objects.front().mesh, 2); }, "Loop subdivision to "},
        {"surface tessellation",
         [] {
             (void)EditableSurface(subdivisionDefinition(cubeCage(), SubdivisionSettings{5, SubdivisionMode::Limit}));
         },
         "tessellating the subdivision surface into about 12288 triangles needs about 2.3 MiB"},
        {"animation", [] { (void)loadAnimation(test::testDataPath("animations/bar").string()); }, "poses of "},
    };
}

/// `text` as a gzip member (zlib's deflate with the gzip wrapper).
std::string gzipped(const std::string& text)
{
    z_stream stream{};
    if (deflateInit2(&stream, Z_BEST_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        return {};
    std::string out(deflateBound(&stream, uLong(text.size())), '\0');
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
    stream.avail_in = uInt(text.size());
    stream.next_out = reinterpret_cast<Bytef*>(out.data());
    stream.avail_out = uInt(out.size());
    deflate(&stream, Z_FINISH);
    out.resize(stream.total_out);
    deflateEnd(&stream);
    return out;
}

} // namespace

class TestMemoryBudget : public QObject {
    Q_OBJECT
private slots:
    void cleanup() { qunsetenv("TRIMLAB_MEMORY_BUDGET"); }
    void readsTheBudget();
    void jobsBeyondTheBudgetAreRefused();
    void jobsWithinTheBudgetRun();
    void decompressionChecksEachGrowth();
};

// 4 MiB of comment lines compress to a few KiB: under a 1 MiB budget the decompression
// stops at the growth that would pass it, with a load error naming the file.
void TestMemoryBudget::decompressionChecksEachGrowth()
{
    std::string mesh = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    while (mesh.size() < (4u << 20))
        mesh += "# padding\n";
    const std::string bytes = gzipped(mesh);
    QVERIFY(!bytes.empty() && bytes.size() < (64 << 10));
    qputenv("TRIMLAB_MEMORY_BUDGET", "1M");
    std::string message;
    try {
        (void)loadMeshFromMemory(bytes, "obj.gz", "bomb.obj.gz");
    } catch (const MeshLoadError& e) {
        message = e.what();
    }
    QVERIFY2(message.starts_with("bomb.obj.gz: decompressing the gzip data (") &&
                 message.find("more than the memory budget of 1.0 MiB") != std::string::npos,
             message.c_str());
    qunsetenv("TRIMLAB_MEMORY_BUDGET");
    QCOMPARE(loadMeshFromMemory(bytes, "obj.gz", "bomb.obj.gz").positions.size(), std::size_t(3));
}

void TestMemoryBudget::readsTheBudget()
{
    qunsetenv("TRIMLAB_MEMORY_BUDGET");
    const std::uint64_t defaultBudget = memoryBudgetBytes();
    QVERIFY(defaultBudget > (std::uint64_t(64) << 20)); // half of any machine that runs the tests
    qputenv("TRIMLAB_MEMORY_BUDGET", "512M");
    QCOMPARE(memoryBudgetBytes(), std::uint64_t(512) << 20);
    qputenv("TRIMLAB_MEMORY_BUDGET", "1.5G");
    QCOMPARE(memoryBudgetBytes(), std::uint64_t(1536) << 20);
    qputenv("TRIMLAB_MEMORY_BUDGET", "4096");
    QCOMPARE(memoryBudgetBytes(), std::uint64_t(4096));
    qputenv("TRIMLAB_MEMORY_BUDGET", "lots");
    QCOMPARE(memoryBudgetBytes(), defaultBudget); // unreadable: the default
    QCOMPARE(formatMemory(512), std::string("512 bytes"));
    QCOMPARE(formatMemory(std::uint64_t(3) << 29), std::string("1.5 GiB"));
}

void TestMemoryBudget::jobsBeyondTheBudgetAreRefused()
{
    qputenv("TRIMLAB_MEMORY_BUDGET", "64");
    for (const Job& job : jobs()) {
        const std::string message = budgetError(job.run);
        QVERIFY2(message.find(job.message) != std::string::npos,
                 qPrintable(QString("%1: %2").arg(job.name, message.c_str())));
        QVERIFY2(message.find("more than the memory budget of 64 bytes (set by TRIMLAB_MEMORY_BUDGET)") !=
                     std::string::npos,
                 message.c_str());
    }
    // The animation's refusal names where it came from.
    const std::string animation = budgetError(jobs().back().run);
    QVERIFY2(animation.find("bar") != std::string::npos, animation.c_str());
}

void TestMemoryBudget::jobsWithinTheBudgetRun()
{
    qunsetenv("TRIMLAB_MEMORY_BUDGET");
    for (const Job& job : jobs()) {
        const std::string message = budgetError(job.run);
        QVERIFY2(message.empty(), qPrintable(QString("%1: %2").arg(job.name, message.c_str())));
    }
}

QTEST_GUILESS_MAIN(TestMemoryBudget)
#include "tst_memory_budget.moc"
