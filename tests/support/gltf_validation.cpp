#include "gltf_validation.h"

#include <QProcess>
#include <QtTest>

namespace trimlab::test {

void requireValidGltf(const std::filesystem::path& file)
{
    const QString script = QStringLiteral(TRIMLAB_SOURCE_DIR "/scripts/gltf-validator");
    QProcess validator;
    validator.setProcessChannelMode(QProcess::MergedChannels);
    validator.start(script, {QString::fromStdString(file.string())});
    QVERIFY2(validator.waitForStarted(), qPrintable("cannot start " + script));
    QVERIFY2(validator.waitForFinished(300000), "the glTF validator did not finish within 5 minutes");
    const QString output = QString::fromUtf8(validator.readAll());
    qInfo().noquote() << output.trimmed();
    QVERIFY2(validator.exitStatus() == QProcess::NormalExit, qPrintable("the validator crashed:\n" + output));
    QVERIFY2(validator.exitCode() != 2, qPrintable("the glTF validator could not run (exit 2); it needs Node.js, "
                                                   "npm and a reachable npm registry on first use:\n" +
                                                   output));
    QVERIFY2(validator.exitCode() == 0, qPrintable("the glTF validator reports errors:\n" + output));
    QVERIFY2(output.contains(": 0 errors,"), qPrintable(output));
}

} // namespace trimlab::test
