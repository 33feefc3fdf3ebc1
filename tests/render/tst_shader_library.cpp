// Every program in the catalog compiles and links in a real OpenGL 4.3 context, every
// assembled shader passes glslangValidator, and build errors carry numbered source.
#include "render/gl/gl_error.h"
#include "render/gl/shader_library.h"
#include "render/gl/shader_source.h"
#include "gl_test_context.h"
#include "test_paths.h"

#include <QFile>
#include <QFileInfo>
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
    void noDeletedProgramStaysCurrent();

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
    int built = 0;
    for (const ProgramDescription& program : programCatalog()) {
        for (const ProgramVariant& variant : program.variants) {
            if (variant.requiredExtension && !m_context->capabilities().hasExtension(variant.requiredExtension)) {
                qInfo("%s %s: needs %s, not in this context (glslangValidator still checks it)",
                      qPrintable(program.name), qPrintable(variant.defines.join(' ')), variant.requiredExtension);
                continue;
            }
            try {
                QVERIFY(library.program(program.name, variant.defines) != 0);
                ++built;
            } catch (const ShaderBuildError& e) {
                QFAIL(e.what());
            }
        }
    }
    QVERIFY(built > 0);
}

// A shader file no program uses is dead code (or a program missing from the catalog).
void TestShaderLibrary::everyShaderFileIsUsed()
{
    QStringList used;
    for (const ProgramDescription& program : programCatalog()) {
        for (const QString& file : program.files) {
            for (const SourceOrigin& origin : assembleShader(file, program.variants.front().defines).origins)
                if (!used.contains(origin.file))
                    used << origin.file;
        }
    }
    for (const QString& file : embeddedShaderFiles())
        QVERIFY2(used.contains(file), qPrintable(file + " is not used by any program in programCatalog()"));
}

namespace {

// glslang 12 (Debian 12) accepts the fragment-shader-interlock layouts only when it
// targets SPIR-V at #version 450, although drivers take them at 430. Variants that need
// such an extension are therefore checked in that mode (same code, version line raised);
// all others exactly as the driver gets them.
QStringList glslangArguments(const ProgramVariant& variant, QByteArray& text, const QString& path)
{
    if (!variant.requiredExtension)
        return {path};
    text.replace("#version 430 core", "#version 450 core");
    return {"-G", "--auto-map-locations", "-o", "/dev/null", path};
}

} // namespace

void TestShaderLibrary::glslangValidatorAcceptsAssembledSources()
{
#ifndef TRIMLAB_GLSLANG_VALIDATOR
    QSKIP("glslangValidator not found at configure time (package glslang-tools)");
#else
    // The path found at configure time: a build carried to another machine (the GPU
    // check's bundle) may not have the tool there.
    if (!QFileInfo::exists(QStringLiteral(TRIMLAB_GLSLANG_VALIDATOR)))
        QSKIP("glslangValidator, found at configure time, is not on this machine (package glslang-tools)");
    int checked = 0;
    for (const ProgramDescription& program : programCatalog()) {
        for (std::size_t v = 0; v < program.variants.size(); ++v) {
            for (const QString& file : program.files) {
                QByteArray text = assembleShader(file, program.variants[v].defines).text;
                const QString path = QString::fromStdString(
                    (test::outputDir() / (std::to_string(v) + "-" + file.toStdString())).string());
                const QStringList arguments = glslangArguments(program.variants[v], text, path);
                QFile out(path);
                QVERIFY(out.open(QIODevice::WriteOnly));
                out.write(text);
                out.close();
                QProcess validator;
                validator.start(QStringLiteral(TRIMLAB_GLSLANG_VALIDATOR), arguments);
                QVERIFY2(validator.waitForFinished(60000), qPrintable(validator.errorString()));
                QVERIFY2(validator.exitCode() == 0,
                         qPrintable(file + " " + program.variants[v].defines.join(' ') + ":\n" +
                                    QString::fromUtf8(validator.readAllStandardOutput())));
                ++checked;
            }
        }
    }
    QVERIFY(checked > 0);
#endif
}

// kplus_resolve.frag refuses to build without K_MAX; the error must show the numbered
// source line and where it came from.
void TestShaderLibrary::missingDefineReportsNumberedSource()
{
    ShaderLibrary library(currentGlFunctions());
    try {
        library.program(QStringLiteral("kplus_resolve"), {});
        QFAIL("kplus_resolve built without K_MAX");
    } catch (const ShaderBuildError& e) {
        const QString message = QString::fromUtf8(e.what());
        QVERIFY2(message.contains("K_MAX"), qPrintable(message));
        QVERIFY2(message.contains(">>"), qPrintable(message));
        QVERIFY2(message.contains("[kplus_resolve.frag:"), qPrintable(message));
    }
}

// A library that goes while one of its programs is current leaves none current: code that
// saves and restores the current program (OpenSubdiv's evaluator) would otherwise restore
// a deleted name (GL_INVALID_VALUE; with a driver that reuses names, a stranger's program).
// Another library's current program is left alone.
void TestShaderLibrary::noDeletedProgramStaysCurrent()
{
    GlFunctions& gl = currentGlFunctions();
    const auto currentProgram = [&gl] {
        GLint current = -1;
        gl.glGetIntegerv(GL_CURRENT_PROGRAM, &current);
        return current;
    };
    ShaderLibrary kept(gl);
    const GLuint keptProgram = kept.program(QStringLiteral("vertex_normals"));
    {
        ShaderLibrary going(gl);
        gl.glUseProgram(going.program(QStringLiteral("vertex_normals")));
        QVERIFY(currentProgram() != 0);
    }
    QCOMPARE(currentProgram(), 0);
    {
        ShaderLibrary going(gl);
        (void)going.program(QStringLiteral("vertex_normals"));
        gl.glUseProgram(keptProgram);
    }
    QCOMPARE(currentProgram(), GLint(keptProgram));
    gl.glUseProgram(0);
    QCOMPARE(gl.glGetError(), GLenum(GL_NO_ERROR));
}

QTEST_MAIN(TestShaderLibrary)
#include "tst_shader_library.moc"
