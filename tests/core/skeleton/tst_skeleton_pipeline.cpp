// The one skeleton operation of `trimlab skeleton` and the Skeleton panel
// (core/skeleton/skeleton_pipeline.h) on a coarse generated star: the rig, weights and
// evaluations of a run describe the mesh given and equal the stages run by hand; a rig-only
// re-run keeps the curve skeleton and changes only what its options change; refused meshes
// and options throw their typed errors; progress names every stage in order; a stop
// request throws OperationCancelled.
#include "core/skeleton/skeleton_pipeline.h"

#include "skeleton_shapes.h"
#include "task_recording.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

using namespace trimlab;

namespace {

// Three arms around a hub, meshed coarsely (about 1.5k vertices) so that a run takes well
// under a second; still closed, manifold and connected.
constexpr double kCell = 0.12;

// "" when `w` holds, for every vertex of `mesh`, used slots of bones of `rig` with weights
// in (0, 1] summing to 1; else the first problem.
QString weightProblem(const BoneWeights& w, const SkeletonRig& rig, const TriangleMesh& mesh)
{
    if (w.vertexCount() != mesh.vertexCount())
        return QString("%1 weighted vertices for %2").arg(w.vertexCount()).arg(mesh.vertexCount());
    for (std::size_t v = 0; v < w.vertexCount(); ++v) {
        double sum = 0.0;
        for (std::size_t k = 0; k < kBoneInfluences; ++k) {
            const int bone = w.bones[v][k];
            if (bone >= int(rig.bones.size()) || (bone >= 0) != (w.weights[v][k] > 0.0f))
                return QString("vertex %1 slot %2: bone %3, weight %4").arg(v).arg(k).arg(bone).arg(w.weights[v][k]);
            sum += double(w.weights[v][k]);
        }
        if (std::abs(sum - 1.0) > 1e-5)
            return QString("vertex %1: weights sum to %2").arg(v).arg(sum);
    }
    return {};
}

// "" when the heat terms were made with the constant c (H_jj = k·c/d², k the visible
// nearest bones) and most vertices see a bone; else the first problem.
QString heatProblem(const BoneHeatTerms& terms, double c)
{
    std::size_t heated = 0;
    for (std::size_t v = 0; v < terms.heat.size(); ++v) {
        const std::size_t k = terms.visibleCount(v);
        const double expected = double(k) * c / (terms.distance[v] * terms.distance[v]);
        if (std::abs(terms.heat[v] - expected) > 1e-9 * expected)
            return QString("vertex %1: H_jj %2, expected %3 (c = %4, k = %5)")
                .arg(v)
                .arg(terms.heat[v])
                .arg(expected)
                .arg(c)
                .arg(k);
        heated += k > 0 ? 1 : 0;
    }
    if (heated <= terms.heat.size() / 2)
        return QString("only %1 of %2 vertices see a bone").arg(heated).arg(terms.heat.size());
    return {};
}

void compareRigs(const SkeletonRig& a, const SkeletonRig& b)
{
    QCOMPARE(a.joints, b.joints);
    QCOMPARE(a.parent, b.parent);
    QCOMPARE(a.root, b.root);
    QCOMPARE(a.vertexJoint, b.vertexJoint);
    QCOMPARE(a.bones.size(), b.bones.size());
    for (std::size_t i = 0; i < a.bones.size(); ++i) {
        QCOMPARE(a.bones[i].head, b.bones[i].head);
        QCOMPARE(a.bones[i].tail, b.bones[i].tail);
        QCOMPARE(a.bones[i].parentBone, b.bones[i].parentBone);
    }
}

void compareWeights(const BoneWeights& a, const BoneWeights& b)
{
    QVERIFY(a.bones == b.bones);
    QVERIFY(a.weights == b.weights);
}

void compareEvaluations(const SkeletonEvaluation& a, const SkeletonEvaluation& b)
{
    QCOMPARE(a.nodeCount, b.nodeCount);
    QCOMPARE(a.edgeCount, b.edgeCount);
    QCOMPARE(a.length, b.length);
    QCOMPARE(a.nodesInside, b.nodesInside);
    QCOMPARE(a.samples, b.samples);
    QCOMPARE(a.edgesLeaving, b.edgesLeaving);
    QCOMPARE(a.maxCoverage, b.maxCoverage);
    QCOMPARE(a.meanCoverage, b.meanCoverage);
    QCOMPARE(a.components, b.components);
    QCOMPARE(a.cycles, b.cycles);
    QCOMPARE(a.diagonal, b.diagonal);
}

// The star with its last triangle removed: a hole of three boundary edges.
TriangleMesh withHole(TriangleMesh mesh)
{
    mesh.triangles.pop_back();
    return mesh;
}

// Two stars side by side: two components.
TriangleMesh twoCopies(const TriangleMesh& mesh)
{
    TriangleMesh both = mesh;
    const auto offset = static_cast<unsigned>(mesh.vertexCount());
    for (const glm::vec3& p : mesh.positions)
        both.positions.push_back(p + glm::vec3(10.0f, 0.0f, 0.0f));
    for (const glm::uvec3& t : mesh.triangles)
        both.triangles.push_back(t + glm::uvec3(offset));
    return both;
}

template <class Error>
QString refusal(const TriangleMesh& mesh, const SkeletonPipelineOptions& options)
{
    try {
        (void)runSkeletonPipeline(mesh, options);
    } catch (const Error& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

} // namespace

class TestSkeletonPipeline : public QObject {
    Q_OBJECT

    TriangleMesh m_mesh;
    SkeletonPipelineOptions m_options;
    std::optional<SkeletonResult> m_full;
    std::vector<std::string> m_fullStages;

private slots:
    void initTestCase()
    {
        m_mesh = test::Star{}.mesh(kCell);
        m_options.heatConstant = 0.5;
        test::StageRecorder log;
        m_full = runSkeletonPipeline(m_mesh, m_options, log.control());
        m_fullStages = log.stages;
        qInfo("star: %zu vertices, %zu curve nodes, %zu joints, %.0f ms", m_mesh.vertexCount(),
              m_full->extraction->curve.nodes.size(), m_full->rig.joints.size(), m_full->totalMs());
    }

    // The heat constant and the contraction's factorization reach the weights.
    void boneHeatOptionsComeFromThePipelineOptions()
    {
        SkeletonPipelineOptions options;
        options.heatConstant = 0.22;
        options.extraction.contraction.backend = SparseBackend::EigenSimplicialLdlt;
        options.extraction.contraction.ordering = SparseOrdering::Amd;
        const BoneHeatOptions heat = boneHeatOptions(options);
        QCOMPARE(heat.terms.heatConstant, 0.22);
        QCOMPARE(heat.backend, SparseBackend::EigenSimplicialLdlt);
        QCOMPARE(heat.ordering, SparseOrdering::Amd);
    }

    // A full run: the rig is the extraction's, the weights and both evaluations are those
    // of the mesh given, made as the stages would make them one by one.
    void fullRunDescribesTheMesh()
    {
        const SkeletonResult& r = *m_full;
        QCOMPARE(r.kind, SkeletonRunKind::Full);
        QVERIFY(r.extraction && r.weights);
        QCOMPARE(r.options.heatConstant, m_options.heatConstant);
        QCOMPARE(r.options.extraction.targetNodes, m_options.extraction.targetNodes);
        compareRigs(r.rig, r.extraction->rig);
        QCOMPARE(r.rig.vertexJoint.size(), m_mesh.vertexCount());
        QCOMPARE(r.extraction->curve.vertexNode.size(), m_mesh.vertexCount());
        QVERIFY(r.rig.joints.size() >= 4 && r.rig.joints.size() <= std::size_t(m_options.extraction.targetNodes));

        QCOMPARE(r.weights->boneCount(), r.rig.bones.size());
        const QString problem = weightProblem(r.weights->weights(), r.rig, m_mesh);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        compareWeights(r.weights->weights(), BoneHeatSolver(m_mesh, r.rig, boneHeatOptions(m_options)).weights());
        const QString heat = heatProblem(r.weights->heatTerms(), m_options.heatConstant);
        QVERIFY2(heat.isEmpty(), qPrintable(heat));

        const SkeletonEvaluator evaluator(m_mesh);
        QCOMPARE(r.curveQuality.nodeCount, int(r.extraction->curve.nodes.size()));
        QCOMPARE(r.rigQuality.nodeCount, int(r.rig.joints.size()));
        QCOMPARE(r.rigQuality.edgeCount, int(r.rig.bones.size()));
        compareEvaluations(r.curveQuality, evaluator.evaluate(skeletonGraph(r.extraction->curve)));
        compareEvaluations(r.rigQuality, evaluator.evaluate(skeletonGraph(r.rig)));

        QVERIFY(r.times.contractionMs > 0.0 && r.weightsMs > 0.0 && r.evaluationMs > 0.0);
        QCOMPARE(r.totalMs(), r.times.contractionMs + r.times.simplificationMs + r.times.refinementMs +
                                  r.times.selectionMs + r.weightsMs);
    }

    void fullRunReportsEveryStageInOrder()
    {
        const std::vector<std::string> expected{"contraction", "simplification", "refinement", "selection",
                                                "visibility",  "weights",        "evaluation"};
        QCOMPARE(m_fullStages, expected);
    }

    // Fewer joints and another root: the same curve skeleton (shared, not recomputed),
    // the rig selectRig makes of it, new weights for that rig and the rig's evaluation;
    // the curve's evaluation is kept.
    void rigOnlyRerunKeepsTheCurve()
    {
        const SkeletonResult& full = *m_full;
        SkeletonPipelineOptions options = m_options;
        options.extraction.targetNodes = 8;
        options.extraction.rootJoint = 2;
        test::StageRecorder log;
        const SkeletonResult r = rerunSkeletonRig(m_mesh, full, options, log.control());
        QCOMPARE(log.stages, (std::vector<std::string>{"selection", "visibility", "weights", "evaluation"}));
        QCOMPARE(r.kind, SkeletonRunKind::RigOnly);
        QCOMPARE(r.extraction.get(), full.extraction.get());
        QCOMPARE(r.options.extraction.targetNodes, 8);

        const SkeletonRig expected = selectRig(full.extraction->curve, m_mesh, 8, 2);
        compareRigs(r.rig, expected);
        QCOMPARE(r.rig.root, 2);
        QVERIFY(r.rig.joints.size() <= 8 && r.rig.joints.size() < full.rig.joints.size());
        QCOMPARE(r.weights->boneCount(), r.rig.bones.size());
        const QString problem = weightProblem(r.weights->weights(), r.rig, m_mesh);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        compareWeights(r.weights->weights(), BoneHeatSolver(m_mesh, expected, boneHeatOptions(options)).weights());

        compareEvaluations(r.curveQuality, full.curveQuality);
        compareEvaluations(r.rigQuality, SkeletonEvaluator(m_mesh).evaluate(skeletonGraph(r.rig)));
        QCOMPARE(r.rigQuality.nodeCount, int(r.rig.joints.size()));

        QCOMPARE(r.times.contractionMs, 0.0);
        QCOMPARE(r.times.simplificationMs, 0.0);
        QCOMPARE(r.times.refinementMs, 0.0);
        QVERIFY(r.weightsMs > 0.0);
    }

    // A re-run with the run's own options gives the run's rig and weights back; one with
    // only another heat constant keeps the rig and changes the weights.
    void rigOnlyRerunChangesOnlyWhatItsOptionsChange()
    {
        const SkeletonResult& full = *m_full;
        const SkeletonResult same = rerunSkeletonRig(m_mesh, full, m_options);
        compareRigs(same.rig, full.rig);
        compareWeights(same.weights->weights(), full.weights->weights());
        compareEvaluations(same.rigQuality, full.rigQuality);

        SkeletonPipelineOptions hotter = m_options;
        hotter.heatConstant = 2.0;
        const SkeletonResult heat = rerunSkeletonRig(m_mesh, full, hotter);
        compareRigs(heat.rig, full.rig);
        QCOMPARE(heat.options.heatConstant, 2.0);
        QVERIFY(heat.weights->weights().weights != full.weights->weights().weights);
        const QString problem = heatProblem(heat.weights->heatTerms(), 2.0);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        compareEvaluations(heat.rigQuality, full.rigQuality); // the same rig in the same mesh
    }

    // Meshes extraction refuses throw SkeletonInputError naming the problem; options out of
    // range throw std::invalid_argument, from the full run and from the re-run.
    void refusalsAreTyped()
    {
        const QString open = refusal<SkeletonInputError>(withHole(m_mesh), m_options);
        QVERIFY2(open.contains("open") && open.contains("3 boundary edges"), qPrintable(open));
        const QString two = refusal<SkeletonInputError>(twoCopies(m_mesh), m_options);
        QVERIFY2(two.contains("2 components"), qPrintable(two));
        QVERIFY(!refusal<SkeletonInputError>(TriangleMesh{}, m_options).isEmpty());

        SkeletonPipelineOptions noJoints = m_options;
        noJoints.extraction.targetNodes = 0;
        QVERIFY(!refusal<std::invalid_argument>(m_mesh, noJoints).isEmpty());
        SkeletonPipelineOptions cold = m_options;
        cold.heatConstant = 0.0;
        QVERIFY(!refusal<std::invalid_argument>(m_mesh, cold).isEmpty());

        SkeletonPipelineOptions badRoot = m_options;
        badRoot.extraction.rootJoint = 1000;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)rerunSkeletonRig(m_mesh, *m_full, badRoot));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)rerunSkeletonRig(m_mesh, *m_full, cold));
    }

    void stopThrowsOperationCancelled_data()
    {
        QTest::addColumn<QString>("stage");
        QTest::addColumn<bool>("rigOnly");
        QTest::newRow("contraction") << "contraction" << false;
        QTest::newRow("simplification") << "simplification" << false;
        QTest::newRow("weights") << "weights" << false;
        QTest::newRow("re-run, selection") << "selection" << true;
        QTest::newRow("re-run, visibility") << "visibility" << true;
    }

    void stopThrowsOperationCancelled()
    {
        QFETCH(QString, stage);
        QFETCH(bool, rigOnly);
        test::StopAtStage stop{stage.toStdString(), {}};
        const TaskControl control = stop.control();
        if (rigOnly)
            QVERIFY_THROWS_EXCEPTION(OperationCancelled, (void)rerunSkeletonRig(m_mesh, *m_full, m_options, control));
        else
            QVERIFY_THROWS_EXCEPTION(OperationCancelled, (void)runSkeletonPipeline(m_mesh, m_options, control));
        QVERIFY(stop.source.stop_requested()); // the stage was reached
    }
};

QTEST_GUILESS_MAIN(TestSkeletonPipeline)
#include "tst_skeleton_pipeline.moc"
