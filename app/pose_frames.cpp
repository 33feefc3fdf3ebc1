#include "app/pose_frames.h"

#include <QStringList>

namespace trimlab::app {

namespace {

constexpr int kMaxPose = 1000000;

// A pose-number conversion starting at `at` (the '%'): its length and its zero-padded
// width (0: none), or nullopt when the text there is not one.
struct Conversion {
    int length = 0;
    int width = 0;
};

std::optional<Conversion> conversionAt(const QString& text, int at)
{
    int i = at + 1;
    const bool zeros = i < text.size() && text[i] == QLatin1Char('0');
    if (zeros)
        ++i;
    int width = 0;
    int digits = 0;
    while (i < text.size() && text[i].isDigit() && digits < 2) {
        width = 10 * width + text[i].digitValue();
        ++i;
        ++digits;
    }
    // %Nd would pad with spaces: not in a file name.
    if (i >= text.size() || text[i] != QLatin1Char('d') || width > 9 || (digits > 0 && !zeros) ||
        (zeros && digits == 0))
        return std::nullopt;
    return Conversion{i + 1 - at, width};
}

std::optional<int> parsePoseNumber(const QString& text)
{
    bool ok = false;
    const int value = text.trimmed().toInt(&ok);
    if (!ok || value < 0 || value > kMaxPose)
        return std::nullopt;
    return value;
}

} // namespace

std::optional<QString> parsePoseSelection(const QString& pose, const QString& poses, std::optional<PoseSelection>& out)
{
    out.reset();
    if (!pose.isEmpty() && !poses.isEmpty())
        return QStringLiteral("give --pose N (one pose) or --poses A:B (a range), not both");
    if (!pose.isEmpty()) {
        const std::optional<int> n = parsePoseNumber(pose);
        if (!n)
            return QStringLiteral("--pose '%1' is not a pose number (0 to %2)").arg(pose).arg(kMaxPose);
        out = PoseSelection{*n, *n, false};
    } else if (!poses.isEmpty()) {
        const QStringList ends = poses.split(QLatin1Char(':'));
        const std::optional<int> a = ends.size() == 2 ? parsePoseNumber(ends[0]) : std::nullopt;
        const std::optional<int> b = ends.size() == 2 ? parsePoseNumber(ends[1]) : std::nullopt;
        if (!a || !b)
            return QStringLiteral("--poses '%1' is not a range A:B of pose numbers (e.g. 0:47)").arg(poses);
        if (*a > *b)
            return QStringLiteral("--poses %1 runs backwards; give the first pose first (%2:%3)")
                .arg(poses)
                .arg(*b)
                .arg(*a);
        out = PoseSelection{*a, *b, true};
    }
    return std::nullopt;
}

bool hasPoseNumber(const QString& pattern)
{
    int conversions = 0;
    for (int i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != QLatin1Char('%'))
            continue;
        if (i + 1 < pattern.size() && pattern[i + 1] == QLatin1Char('%')) {
            ++i;
            continue;
        }
        const std::optional<Conversion> conversion = conversionAt(pattern, i);
        if (!conversion)
            return false;
        ++conversions;
        i += conversion->length - 1;
    }
    return conversions == 1;
}

QString posePath(const QString& pattern, int pose)
{
    if (!hasPoseNumber(pattern))
        return pattern;
    QString path;
    for (int i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != QLatin1Char('%')) {
            path += pattern[i];
            continue;
        }
        if (pattern[i + 1] == QLatin1Char('%')) { // hasPoseNumber: a '%' is never last
            path += QLatin1Char('%');
            ++i;
            continue;
        }
        const Conversion conversion = *conversionAt(pattern, i);
        path += QStringLiteral("%1").arg(pose, conversion.width, 10, QLatin1Char('0'));
        i += conversion.length - 1;
    }
    return path;
}

} // namespace trimlab::app
