// Every program in the catalog compiles and links in a real OpenGL 4.3 context, every
// assembled shader passes glslangValidator, and build errors carry numbered source.
#include "gl/gl_error.h"
#include "gl/shader_library.h"
#include "gl/shader_source.h"
#include "gl_test_context.h"
#include "test_paths.h"

#include <QFile>
#include <QProcess>
#include <QtTest>

using namespace trimlab;
using namespace trimlab::render;

class TestShaderLibrary : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void everyProgramBuilds();
    void everyShaderFileIsUsed();
    void glslangValidatorAcceptsAssembledSources();
    void missingDefineReportsNumberedSource();

private:
    std::unique_ptr<OffscreenGlContext> m_context;
};

void TestShaderLibrary::initTestCase()
{
    TRIMLAB_INIT_GL_CONTEXT(m_context);
    qInfo("%s", qPrintable(m_context->capabilities().summary()));
}

void TestShaderLibrary::everyProgramBuilds()
{
    ShaderLibrary library(currentGlFunctions());
    for (const ProgramDescription& program : programCatalog()) {
        for (const QStringList& defines : program.representativeDefines) {
            try {
                QVERIFY(library.program(program.name, defines) != 0);
            } catch (const ShaderBuildError& e) {
                QFAIL(e.what());
            }
        }
    }
}

// A shader file no program uses is dead code (or a program missing from the catalog).
void TestShaderLibrary::everyShaderFileIsUsed()
{
    QStringList used;
    for (const ProgramDescription& program : programCatalog()) {
        for (const QString& file : program.files) {
            for (const SourceOrigin& origin : assembleShader(file, program.representativeDefines.front()).origins)
                if (!used.contains(origin.file))
                    used << origin.file;
        }
    }
    for (const QString& file : embeddedShaderFiles())
        QVERIFY2(used.contains(file), qPrintable(file + " is not used by any program in programCatalog()"));
}

void TestShaderLibrary::glslangValidatorAcceptsAssembledSources()
{
#ifndef TRIMLAB_GLSLANG_VALIDATOR
    QSKIP("glslangValidator not found at configure time (package glslang-tools)");
#else
    for (const ProgramDescription& program : programCatalog()) {
        for (const QString& file : program.files) {
            const AssembledShader shader = assembleShader(file, program.representativeDefines.back());
            const QString path = QString::fromStdString((test::outputDir() / file.toStdString()).string());
            QFile out(path);
            QVERIFY(out.open(QIODevice::WriteOnly));
            out.write(shader.text);
            out.close();
            QProcess validator;
            validator.start(QStringLiteral(TRIMLAB_GLSLANG_VALIDATOR), {path});
            QVERIFY(validator.waitForFinished(60000));
            QVERIFY2(validator.exitCode() == 0,
                     qPrintable(file + ":\n" + QString::fromUtf8(validator.readAllStandardOutput())));
        }
    }
#endif
}

// trim_resolve.frag refuses to build without K_MAX; the error must show the numbered
// source line and where it came from.
void TestShaderLibrary::missingDefineReportsNumberedSource()
{
    ShaderLibrary library(currentGlFunctions());
    try {
        library.program(QStringLiteral("trim_resolve"), {});
        QFAIL("trim_resolve built without K_MAX");
    } catch (const ShaderBuildError& e) {
        const QString message = QString::fromUtf8(e.what());
        QVERIFY2(message.contains("K_MAX"), qPrintable(message));
        QVERIFY2(message.contains(">>"), qPrintable(message));
        QVERIFY2(message.contains("[trim_resolve.frag:"), qPrintable(message));
    }
}

QTEST_MAIN(TestShaderLibrary)
#include "tst_shader_library.moc"
