#include "render/gl/shader_source.h"

#include "render/gl/bindings.h"
#include "render/gl/gl_error.h"

#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QSet>

namespace trimlab::render {

namespace {

QStringList readLines(const QString& file)
{
    QFile f(shaderResourceRoot() + QLatin1Char('/') + file);
    if (!f.open(QIODevice::ReadOnly))
        throw ShaderBuildError("Shader file '" + file.toStdString() + "' is missing from the embedded resources.");
    return QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'));
}

struct Assembler {
    AssembledShader out;
    QSet<QString> included;

    void appendLine(const QString& text, const QString& file, int line)
    {
        out.text += text.toUtf8();
        out.text += '\n';
        out.origins.push_back({file, line});
    }

    // Appends lines[from..] of `file`, expanding #include lines (each file at most once).
    void appendLines(const QString& file, const QStringList& lines, int from)
    {
        static const QRegularExpression includeLine(QStringLiteral(R"re(^\s*#\s*include\s+"([^"]+)"\s*$)re"));
        for (int i = from; i < lines.size(); ++i) {
            const QRegularExpressionMatch m = includeLine.match(lines[i]);
            if (m.hasMatch())
                appendFile(m.captured(1));
            else
                appendLine(lines[i], file, i + 1);
        }
    }

    void appendFile(const QString& file)
    {
        if (included.contains(file))
            return;
        included.insert(file);
        appendLines(file, readLines(file), 0);
    }
};

} // namespace

QString shaderResourceRoot()
{
    return QStringLiteral(":/shaders");
}

AssembledShader assembleShader(const QString& file, const QStringList& defines)
{
    const QStringList lines = readLines(file);
    if (lines.isEmpty() || !lines.first().trimmed().startsWith(QLatin1String("#version")))
        throw ShaderBuildError("Shader file '" + file.toStdString() + "' must start with a #version line.");
    Assembler a;
    a.out.file = file;
    a.included.insert(file);
    a.appendLine(lines.first(), file, 1);
    for (const QString& d : binding::glslBindingDefines() + defines)
        a.appendLine(QStringLiteral("#define ") + d, QStringLiteral("<define>"), 0);
    a.appendLines(file, lines, 1);
    return a.out;
}

QString AssembledShader::excerpt(int line, int context) const
{
    const QList<QByteArray> lines = text.split('\n');
    QString result;
    const int first = std::max(1, line - context);
    const int last = std::min(int(origins.size()), line + context);
    for (int n = first; n <= last; ++n) {
        const SourceOrigin& o = origins[std::size_t(n - 1)];
        result += QStringLiteral("%1%2 | %3  [%4:%5]\n")
                      .arg(n == line ? QStringLiteral(">>") : QStringLiteral("  "))
                      .arg(n, 4)
                      .arg(QString::fromUtf8(lines.value(n - 1)))
                      .arg(o.file)
                      .arg(o.line);
    }
    return result;
}

QStringList embeddedShaderFiles()
{
    QStringList files;
    const QString root = shaderResourceRoot() + QLatin1Char('/');
    QDirIterator it(shaderResourceRoot(), QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext())
        files << it.next().mid(root.size());
    files.sort();
    return files;
}

} // namespace trimlab::render
