#include "render/gl/shader_library.h"

#include "render/gl/gl_error.h"
#include "render/gl/shader_source.h"

#include <QRegularExpression>

#include <algorithm>

namespace trimlab::render {

const std::vector<ProgramDescription>& programCatalog()
{
    // K_MAX is the compile-time capacity of a pixel's local fragment array in the
    // resolve pass; the renderer compiles one variant per k the user picks. Interlock
    // variants only build where the driver has the extension (representativeDefines are
    // also checked by glslangValidator, which knows every extension). CAPPING,
    // OBJECT_WINDINGS N, COPLANAR_COUNT and TRANSPARENCY are the interior-inspection
    // variants (TrimRenderer::prepareInspection).
    static const std::vector<ProgramDescription> catalog = {
        {"pixel_state_clear", {"pixel_state_clear.comp"}, {{}}},
        {"kplus_store",
         {"scene.vert", "kplus_store.frag"},
         {{{}},
          {{"DYNAMIC_RULES"}},
          {{"OBJECT_WINDINGS 3"}},
          {{"KPLUS_HEAP"}},
          {{"KPLUS_INTERLOCK_ARB"}, "GL_ARB_fragment_shader_interlock"},
          {{"KPLUS_HEAP", "KPLUS_INTERLOCK_ARB"}, "GL_ARB_fragment_shader_interlock"}}},
        {"kplus_resolve",
         {"fullscreen.vert", "kplus_resolve.frag"},
         {{{"K_MAX 1"}},
          {{"K_MAX 16"}},
          {{"K_MAX 64"}},
          {{"K_MAX 16", "DYNAMIC_RULES"}},
          {{"K_MAX 16", "DYNAMIC_RULES", "DYNAMIC_CHARACTERIZE"}},
          {{"K_MAX 16", "CAPPING"}},
          {{"K_MAX 16", "CAPPING", "OBJECT_WINDINGS 3", "COPLANAR_COUNT"}},
          {{"K_MAX 16", "TRANSPARENCY"}},
          {{"K_MAX 16", "CAPPING", "OBJECT_WINDINGS 3", "COPLANAR_COUNT", "TRANSPARENCY"}}}},
        // buffer methods (S-buffer, K+B-SB, AB_FP, AB_LL)
        {"fragment_count", {"scene.vert", "fragment_count.frag"}, {{}, {{"DYNAMIC_RULES"}}, {{"OBJECT_WINDINGS 3"}}}},
        {"sbuffer_address", {"sbuffer_address.comp"}, {{}}},
        {"sbuffer_prefix", {"sbuffer_prefix.comp"}, {{}}},
        {"sbuffer_offset", {"sbuffer_offset.comp"}, {{}}},
        {"sbuffer_store", {"scene.vert", "sbuffer_store.frag"}, {{}}},
        {"sbuffer_resolve",
         {"fullscreen.vert", "sbuffer_resolve.frag"},
         {{{"LIST_MAX 256"}},
          {{"LIST_MAX 256", "DYNAMIC_RULES"}},
          {{"LIST_MAX 256", "DYNAMIC_RULES", "DYNAMIC_CHARACTERIZE"}},
          {{"LIST_MAX 256", "CAPPING", "OBJECT_WINDINGS 3", "COPLANAR_COUNT"}},
          {{"LIST_MAX 256", "CAPPING", "OBJECT_WINDINGS 3", "COPLANAR_COUNT", "TRANSPARENCY"}}}},
        {"kplus_sbuffer_store",
         {"scene.vert", "kplus_store.frag"},
         {{{"KPLUS_NODE_REGION"}}, {{"KPLUS_INTERLOCK_ARB", "KPLUS_NODE_REGION"}, "GL_ARB_fragment_shader_interlock"}}},
        {"kplus_sbuffer_resolve",
         {"fullscreen.vert", "kplus_resolve.frag"},
         {{{"KPLUS_NODE_REGION", "K_MAX 1"}},
          {{"KPLUS_NODE_REGION", "K_MAX 16"}},
          {{"KPLUS_NODE_REGION", "K_MAX 64"}},
          {{"KPLUS_NODE_REGION", "K_MAX 16", "CAPPING", "OBJECT_WINDINGS 3", "COPLANAR_COUNT"}},
          {{"KPLUS_NODE_REGION", "K_MAX 16", "CAPPING", "OBJECT_WINDINGS 3", "COPLANAR_COUNT", "TRANSPARENCY"}}}},
        {"abuffer_fixed_store",
         {"scene.vert", "abuffer_fixed_store.frag"},
         {{}, {{"DYNAMIC_RULES"}}, {{"OBJECT_WINDINGS 3"}}}},
        {"abuffer_fixed_resolve",
         {"fullscreen.vert", "abuffer_fixed_resolve.frag"},
         {{{"K_MAX 1"}},
          {{"K_MAX 16"}},
          {{"K_MAX 64"}},
          {{"K_MAX 16", "DYNAMIC_RULES", "DYNAMIC_CHARACTERIZE"}},
          {{"K_MAX 16", "CAPPING", "OBJECT_WINDINGS 3", "COPLANAR_COUNT"}},
          {{"K_MAX 16", "CAPPING", "OBJECT_WINDINGS 3", "COPLANAR_COUNT", "TRANSPARENCY"}}}},
        {"head_clear", {"head_clear.comp"}, {{}}},
        {"abuffer_list_store",
         {"scene.vert", "abuffer_list_store.frag"},
         {{}, {{"DYNAMIC_RULES"}}, {{"OBJECT_WINDINGS 3"}}}},
        {"abuffer_list_resolve",
         {"fullscreen.vert", "abuffer_list_resolve.frag"},
         {{{"LIST_MAX 256"}},
          {{"LIST_MAX 256", "DYNAMIC_RULES"}},
          {{"LIST_MAX 256", "DYNAMIC_RULES", "DYNAMIC_CHARACTERIZE"}},
          {{"LIST_MAX 256", "CAPPING", "OBJECT_WINDINGS 3", "COPLANAR_COUNT"}},
          {{"LIST_MAX 256", "CAPPING", "OBJECT_WINDINGS 3", "COPLANAR_COUNT", "TRANSPARENCY"}}}},
        // peeling methods (F2B, DUAL, two-pass)
        {"peeling_clear", {"peeling_clear.comp"}, {{}}},
        {"peel_f2b", {"scene.vert", "peel_f2b.frag"}, {{}}},
        {"peel_f2b_walk", {"fullscreen.vert", "peel_f2b_walk.frag"}, {{}}},
        {"peel_dual", {"scene.vert", "peel_dual.frag"}, {{}}},
        {"peel_dual_walk", {"fullscreen.vert", "peel_dual_walk.frag"}, {{}}},
        {"peeling_resolve", {"fullscreen.vert", "peeling_resolve.frag"}, {{}, {{"CAPPING"}}}},
        {"two_pass_count", {"scene.vert", "two_pass_count.frag"}, {{}}},
        {"two_pass_closest", {"scene.vert", "two_pass_closest.frag"}, {{}}},
        {"two_pass_resolve", {"fullscreen.vert", "two_pass_resolve.frag"}, {{}, {{"CAPPING"}}}},
        // geometry rewritten on the GPU: skinned poses and their normals (frame/gpu_skinning.h)
        {"skinning", {"skinning.comp"}, {{}}},
        {"vertex_normals", {"vertex_normals.comp"}, {{}}},
    };
    return catalog;
}

namespace {

GLenum stageOf(const QString& file)
{
    if (file.endsWith(QLatin1String(".vert")))
        return GL_VERTEX_SHADER;
    if (file.endsWith(QLatin1String(".frag")))
        return GL_FRAGMENT_SHADER;
    if (file.endsWith(QLatin1String(".comp")))
        return GL_COMPUTE_SHADER;
    throw ShaderBuildError("Cannot tell the shader stage of '" + file.toStdString() + "' from its extension.");
}

// Line numbers a driver's info log refers to: Mesa "0:12(5): error", NVIDIA "0(12) : error".
QList<int> reportedLines(const QString& log)
{
    static const QRegularExpression pattern(QStringLiteral(R"(^\s*\d+[:(](\d+)[):(])"),
                                            QRegularExpression::MultilineOption);
    QList<int> lines;
    auto it = pattern.globalMatch(log);
    while (it.hasNext()) {
        const int line = it.next().captured(1).toInt();
        if (!lines.contains(line))
            lines << line;
    }
    return lines;
}

QString compileReport(const AssembledShader& shader, const QString& log, const QStringList& defines)
{
    QString report =
        QStringLiteral("Shader '%1' (defines: %2) failed to compile:\n%3\n")
            .arg(shader.file, defines.isEmpty() ? QStringLiteral("none") : defines.join(", "), log.trimmed());
    for (int line : reportedLines(log))
        report += QStringLiteral("\n") + shader.excerpt(line);
    return report;
}

QString infoLog(GlFunctions& gl, GLuint object, bool isProgram)
{
    GLint length = 0;
    isProgram ? gl.glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
              : gl.glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    QByteArray log(std::max(length, 1), '\0');
    isProgram ? gl.glGetProgramInfoLog(object, length, nullptr, log.data())
              : gl.glGetShaderInfoLog(object, length, nullptr, log.data());
    return QString::fromUtf8(log.constData());
}

} // namespace

ShaderLibrary::ShaderLibrary(GlFunctions& gl) : m_gl(gl)
{
}

ShaderLibrary::~ShaderLibrary()
{
    // A deleted program that is still current lives on, flagged, until another is made
    // current; whoever saved and restores "the current program" (OpenSubdiv's evaluator
    // does) would then bind a dead name: GL_INVALID_VALUE, and on a driver that reuses
    // names (NVIDIA) possibly another object's program. So none of ours stays current.
    GLint current = 0;
    m_gl.glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    if (std::find(m_programs.cbegin(), m_programs.cend(), GLuint(current)) != m_programs.cend())
        m_gl.glUseProgram(0);
    for (GLuint program : std::as_const(m_programs))
        m_gl.glDeleteProgram(program);
}

GLuint ShaderLibrary::program(const QString& name, const QStringList& defines)
{
    const QString key = name + QLatin1Char('|') + defines.join(QLatin1Char(';'));
    if (auto it = m_programs.constFind(key); it != m_programs.constEnd())
        return *it;
    for (const ProgramDescription& description : programCatalog()) {
        if (description.name == name) {
            const GLuint id = build(description, defines);
            m_programs.insert(key, id);
            return id;
        }
    }
    throw ShaderBuildError("No shader program named '" + name.toStdString() + "' in the catalog.");
}

GLuint ShaderLibrary::compileStage(const QString& file, const QStringList& defines)
{
    const AssembledShader shader = assembleShader(file, defines);
    const GLuint id = m_gl.glCreateShader(stageOf(file));
    const char* text = shader.text.constData();
    const GLint length = GLint(shader.text.size());
    m_gl.glShaderSource(id, 1, &text, &length);
    m_gl.glCompileShader(id);
    GLint ok = GL_FALSE;
    m_gl.glGetShaderiv(id, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        const QString log = infoLog(m_gl, id, false);
        m_gl.glDeleteShader(id);
        throw ShaderBuildError(compileReport(shader, log, defines).toStdString());
    }
    return id;
}

GLuint ShaderLibrary::build(const ProgramDescription& description, const QStringList& defines)
{
    const GLuint program = m_gl.glCreateProgram();
    std::vector<GLuint> stages;
    try {
        for (const QString& file : description.files) {
            stages.push_back(compileStage(file, defines));
            m_gl.glAttachShader(program, stages.back());
        }
    } catch (...) {
        for (GLuint s : stages)
            m_gl.glDeleteShader(s);
        m_gl.glDeleteProgram(program);
        throw;
    }
    m_gl.glLinkProgram(program);
    for (GLuint s : stages) {
        m_gl.glDetachShader(program, s);
        m_gl.glDeleteShader(s);
    }
    GLint linked = GL_FALSE;
    m_gl.glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (linked != GL_TRUE) {
        const QString log = infoLog(m_gl, program, true);
        m_gl.glDeleteProgram(program);
        throw ShaderBuildError(QStringLiteral("Shader program '%1' (%2) failed to link:\n%3")
                                   .arg(description.name, description.files.join(", "), log.trimmed())
                                   .toStdString());
    }
    return program;
}

} // namespace trimlab::render
