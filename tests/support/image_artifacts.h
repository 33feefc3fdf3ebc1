#pragma once
/// \file
/// Failure artifacts of image comparisons: actual.png, expected.png and diff.png written
/// next to the test's output, with their paths returned for the failure message.

#include <QImage>
#include <QString>

namespace trimlab::test {

/// Writes `<name>-actual.png`, `<name>-expected.png` and `<name>-diff.png` (the
/// pixels where `disagreementMask` is non-zero in red over a dimmed expected image) into
/// outputDir(); returns a one-line note naming the three files.
QString writeComparisonArtifacts(const QString& name, const QImage& actual, const QImage& expected,
                                 const QImage& disagreementMask);

} // namespace trimlab::test
