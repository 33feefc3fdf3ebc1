#include "ui/render_panel/overflow_advice.h"

#include <QCoreApplication>
#include <QLocale>

#include <algorithm>

namespace trimlab::ui {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("OverflowAdvice", text);
}

std::optional<int> largerK(const render::MethodInfo& info, int k, std::optional<std::uint32_t> largest, bool& exact)
{
    exact = false;
    if (!info.usesK || k >= render::MethodParameters::kMaxK)
        return std::nullopt;
    if (largest && *largest > std::uint32_t(k)) {
        exact = *largest <= std::uint32_t(render::MethodParameters::kMaxK);
        return int(std::min<std::uint32_t>(*largest, render::MethodParameters::kMaxK));
    }
    return std::min(2 * k, render::MethodParameters::kMaxK);
}

QString overflowMessage(const render::MethodInfo& info, const render::FrameCounts& counts, int k)
{
    const QLocale locale;
    QString text =
        tr("%1 pixels unresolved (magenta), %2 fragments lost, %3 pixels overflowed.")
            .arg(locale.toString(qulonglong(counts.unresolvedPixels)),
                 locale.toString(qulonglong(counts.fragmentsLost)), locale.toString(qulonglong(counts.overflowPixels)));
    const QString name = QString::fromUtf8(info.displayName.data(), qsizetype(info.displayName.size()));
    if (info.usesK)
        text += QLatin1Char(' ') + tr("%1 keeps at most k = %2 fragments per pixel.").arg(name).arg(k);
    else
        text += QLatin1Char(' ') + tr("%1 ran out of capacity.").arg(name);
    return text;
}

} // namespace

OverflowAdvice adviseOnOverflow(render::FragmentMethodKind method, const render::FrameCounts& counts,
                                const render::MethodParameters& parameters,
                                std::optional<std::uint32_t> largestPixelCount)
{
    OverflowAdvice advice;
    advice.overflowing = counts.unresolvedPixels > 0 || counts.fragmentsLost > 0;
    if (!advice.overflowing)
        return advice;
    const render::MethodInfo& info = render::methodInfo(method);
    advice.message = overflowMessage(info, counts, parameters.k);
    for (const render::MethodInfo& other : render::fragmentMethods())
        if (!other.bounded && other.kind != method)
            advice.unboundedMethods.push_back(other.kind);
    advice.raiseKTo = largerK(info, parameters.k, largestPixelCount, advice.raiseKHoldsDeepestPixel);
    return advice;
}

} // namespace trimlab::ui
