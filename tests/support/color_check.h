#pragma once
/// \file
/// Color comparison of a GPU frame with the CPU reference's color image, for effects that
/// change colors only (transparency): per pixel the largest channel difference, counted
/// over the pixels whose reference ray hits anything (hitCount > 0), excluding the pixels
/// the GPU flags overflowed or unresolved (bounded methods may lose fragments there).

#include "core/image/rgba_image.h"
#include "core/trim/reference_diagnostics.h"
#include "core/trim/trim_image.h"

#include <QImage>
#include <QString>

#include <optional>

namespace trimlab::test {

struct ColorComparison {
    std::uint64_t compared = 0; ///< pixels with a hit, not flagged by the GPU
    std::uint64_t within = 0;   ///< of those, every channel within the tolerance
    std::uint64_t flagged = 0;  ///< skipped: overflowed or unresolved on the GPU
    int maxDifference = 0;      ///< largest channel difference over compared pixels, in 8-bit steps
    QImage disagreementMask;    ///< Grayscale8, 255 where beyond the tolerance

    [[nodiscard]] double agreement() const { return compared ? double(within) / double(compared) : 0.0; }
    [[nodiscard]] QString summary() const;
};

/// `gpu` is the frame's color image (top row first), `gpuTrim` its read-back ids (for the
/// flags); `tolerance` in 8-bit steps.
[[nodiscard]] ColorComparison compareColors(const QImage& gpu, const TrimImage& gpuTrim, const RgbaImage& reference,
                                            const ReferenceDiagnostics& diagnostics, int tolerance);

/// A picture of a reference color image, for failure artifacts.
[[nodiscard]] QImage rgbaToImage(const RgbaImage& image);

/// nullopt when at least `minimumAgreement` of the compared pixels agree and at least
/// `minimumCompared` pixels were compared; else the reason, with artifacts written under
/// `name` (image_artifacts.h).
[[nodiscard]] std::optional<QString> colorViolation(const ColorComparison& comparison, const QImage& gpu,
                                                    const RgbaImage& reference, const QString& name,
                                                    double minimumAgreement, std::uint64_t minimumCompared);

} // namespace trimlab::test
