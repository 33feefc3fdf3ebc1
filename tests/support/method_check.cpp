#include "method_check.h"

#include "image_artifacts.h"

namespace trimlab::test {

namespace {

QString artifactName(const MethodCase& testCase, render::FragmentMethodKind method)
{
    QString name = QString::fromLatin1(render::methodInfo(method).id.data()) + "-" + testCase.name;
    for (QChar& c : name)
        if (!c.isLetterOrNumber() && c != '-')
            c = '_';
    return name;
}

std::optional<QString> firstViolation(const TrimComparison& comparison, const render::FrameStats& stats, bool bounded,
                                      const MethodCase& testCase, const MethodCriteria& criteria)
{
    const double pixels = double(testCase.width) * testCase.height;
    if (comparison.coveredPixels < criteria.minimumCoverage * pixels)
        return QStringLiteral("the scene covers only %1 pixels: a vacuous case").arg(comparison.coveredPixels);
    const AgreementCriteria shared{criteria.minimumAgreement, criteria.maximumExcluded};
    if (const auto violation = agreementViolation(comparison, shared, bounded, stats.counts.fragmentsLost))
        return QString::fromStdString(*violation);
    return std::nullopt;
}

} // namespace

std::optional<QString> checkMethodAgainstReference(render::TrimRenderer& renderer, render::FragmentMethodKind method,
                                                   const MethodCase& testCase,
                                                   const ReferenceRenderer& referenceRenderer,
                                                   const ReferenceResult& reference, QString* summary,
                                                   const MethodCriteria& criteria)
{
    renderer.setMethod(method);
    renderer.setParameters(testCase.parameters);
    renderer.render(testCase.camera, testCase.settings, testCase.width, testCase.height);
    const TieCheck ties = criteria.allowTies ? referenceTieCheck(referenceRenderer, testCase.camera, testCase.width,
                                                                 testCase.height, testCase.settings)
                                             : TieCheck{};
    return checkFrameAgainstReference(renderer, testCase, reference, ties, summary, criteria);
}

std::optional<QString> checkFrameAgainstReference(render::TrimRenderer& renderer, const MethodCase& testCase,
                                                  const ReferenceResult& reference, const TieCheck& ties,
                                                  QString* summary, const MethodCriteria& criteria)
{
    renderer.finishFrames(); // a pipelined renderer's numbers of the frame its image holds
    const render::FragmentMethodKind method = renderer.method();
    const TrimImage gpu = renderer.readTrimImage();
    const TrimComparison comparison = compareTrimImages(gpu, reference.trim, reference.diagnostics, {}, ties);
    const render::FrameStats& stats = renderer.lastStats();
    const QString text =
        comparison.summary() + QStringLiteral("; %1 geometry passes, %2 fragments stored, %3 lost, %4 ms wall")
                                   .arg(stats.methodStats.geometryPasses)
                                   .arg(stats.counts.fragmentsStored)
                                   .arg(stats.counts.fragmentsLost)
                                   .arg(stats.wallMilliseconds, 0, 'f', 1);
    if (summary)
        *summary = text;
    const bool bounded = render::methodInfo(method).bounded;
    std::optional<QString> violation = firstViolation(comparison, stats, bounded, testCase, criteria);
    if (!violation)
        return std::nullopt;
    const QString files = writeComparisonArtifacts(artifactName(testCase, method), trimImageToPicture(gpu),
                                                   trimImageToPicture(reference.trim), comparison.disagreementMask);
    return *violation + ": " + text + "; " + files;
}

} // namespace trimlab::test
