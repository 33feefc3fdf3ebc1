#pragma once
/// \file
/// The interior-inspection settings of a trim render beyond rule and clipping: capping,
/// CSG of several self-trimmed objects with per-object rules, highlighting of collisions
/// and coplanar fragments, and transparency (X-ray). Plain values shared by the GPU backends, the CPU
/// reference, the GUI panels and the command line (TrimSettings holds one of each).

#include "core/trim/csg_expression.h"
#include "core/trim/static_rule.h"

#include <array>
#include <optional>
#include <string_view>

namespace trimlab {

/// How a cap is drawn. The pattern lives in world space (it does not swim when the
/// camera moves): lines on the clipping plane, `spacing` world units apart.
enum class CapPattern {
    Hatched, ///< two families of lines crossing at right angles (diagonals of the plane's basis)
    Striped, ///< one family of parallel lines
    Solid,   ///< no lines
};

/// Capping (thesis 2.1, 8.1.2, Fig. 8.14): where the kept span of a pixel ray starts at a
/// clipping plane and the point there is interior — under the rule, or under the CSG
/// expression when one is set — the pixel shows the cap: the plane itself, lit flat with
/// the plane's normal, in the front-facing color with the pattern's lines darkened.
/// Behind a cap nothing of that ray is visible; elsewhere the trim shows as without
/// capping. No effect with trimming off (there is no interior then) or without an
/// enabled clipping plane.
struct CapSettings {
    bool enabled = false;
    CapPattern pattern = CapPattern::Hatched;
    /// World units between neighbouring lines (> 0; the CLI derives it from the scene's
    /// size). Values <= 0 or non-finite draw the cap Solid.
    double spacing = 0.05;
    /// Fraction of `spacing` covered by a line, clamped to [0, 1].
    double lineWidth = 0.3;

    friend bool operator==(const CapSettings&, const CapSettings&) = default;
};

/// CSG of the scene's objects (thesis 8.1.2, Algorithm 8.14 for n operands). Without an
/// expression the scene is one self-crossing surface classified by the winding index
/// summed over all objects and TrimSettings::rule (the default, unchanged). With one,
/// each object o < kMaxCsgOperands gets its own winding index w_o and inside bit
/// isInterior(objectRule(o), w_o), the pixel's classification is the expression on those
/// bits, and the shown fragment is the first one (from the span start) whose two sides
/// classify differently. Objects the expression does not mention never change the
/// classification, so none of their fragments is shown.
struct CsgSettings {
    /// The expression; empty (the default) for no CSG.
    CsgExpression expression;
    /// Per-object rules; nullopt (the default) uses TrimSettings::rule. Used whenever
    /// per-object classification happens: CSG, and the "inside another object" test of
    /// collision highlighting.
    std::array<std::optional<StaticRule>, kMaxCsgOperands> objectRules{};

    [[nodiscard]] bool enabled() const { return !expression.empty(); }

    friend bool operator==(const CsgSettings&, const CsgSettings&) = default;
};

/// What the shown fragments are tinted with (thesis Figs. 6.8 right, 6.9, 7.4c).
struct HighlightSettings {
    /// Tint shown fragments red that lie inside another object (object q != own, q <
    /// kMaxCsgOperands, isInterior(objectRule(q), w_q) at the fragment) or where their own
    /// object overlaps itself (|w_own| > 1 on either side of the fragment). Counted per
    /// frame (FrameCounts::collisionPixels).
    bool collisions = false;
    /// Color shown fragments that share their exact depth with other fragments of the
    /// kept span by the size of that coplanar group (Fig. 6.9 palette: 2 red, 3 blue,
    /// 4 green, 5 cyan, 6 aquamarine, 7 fuchsia, 8 yellow, 9+ brown). Counted per frame
    /// (FrameCounts::coplanarPixels).
    bool coplanar = false;

    [[nodiscard]] bool any() const { return collisions || coplanar; }

    friend bool operator==(const HighlightSettings&, const HighlightSettings&) = default;
};

/// How the trimmed solid itself is drawn when transparency is on.
enum class TrimDisplay {
    /// The trimmed solid as without transparency (its first boundary point, or its cap, is
    /// opaque); the fragments the rule removed in front of it are ghost layers over it.
    Opaque,
    /// Every boundary fragment of the trimmed solid in the kept span (caps included) is a
    /// translucent layer; removed fragments are ghost layers between them.
    Translucent,
};

/// Transparency / X-ray (thesis 1.3.3 and Fig. 5.2: order-independent transparency over
/// a pixel's sorted fragments, "accounting for the density between layers", and Fresnel
/// weighted translucency). The trim walk passes every fragment of the kept span in depth
/// order with its classification; core/trim/transparency.h composites them front to back
/// (C += T·α·c, T *= 1 − α) over the background and stops once T < 1/512. Which fragments
/// are layers:
/// - boundary fragments (the two sides classify differently; every fragment with
///   trimming off) are the solid's surface: alpha `layerAlpha` (Translucent), or the
///   first one opaque and the walk ends there (Opaque);
/// - the other fragments of the span (the surface the rule removed: inside the solid or
///   between nested sheets) are ghosts with alpha `ghostAlpha` (0 hides them).
/// - A cap (CapSettings) is the first boundary layer, at the span start.
/// Fragments outside the kept span (clipped away) are never stored, so never drawn.
/// Between two consecutive layers whose interval classifies interior, T is multiplied
/// by exp(−density · distance) (Beer–Lambert; distance in world units along the ray).
/// Fresnel (exponent p > 0): a layer's alpha grows towards grazing angles,
/// α' = α + (1 − α)(1 − |n·v|)^p; a layer whose alpha is 0 stays hidden. Colors are the
/// layers' usual shading (trim_shading.h); the first boundary fragment keeps its
/// highlights. The id texel / TrimPixel stays the first shown point, as without
/// transparency. Out-of-range values are clamped where used (alphas to [0, 1], density
/// and exponent below 0 to 0; non-finite ones count as 0).
struct TransparencySettings {
    bool enabled = false;
    TrimDisplay display = TrimDisplay::Translucent;
    double layerAlpha = 0.4;      ///< opacity of each boundary layer (Translucent), 0–1
    double ghostAlpha = 0.25;     ///< opacity of each removed fragment, 0–1 (0: hidden)
    double density = 0.0;         ///< absorption per world unit inside the solid, >= 0
    double fresnelExponent = 0.0; ///< p of the Fresnel term; 0: off

    friend bool operator==(const TransparencySettings&, const TransparencySettings&) = default;
};

/// Stable names of the cap patterns: "hatched", "striped", "solid".
[[nodiscard]] std::string_view capPatternName(CapPattern pattern);
[[nodiscard]] std::optional<CapPattern> parseCapPattern(std::string_view name);

/// Stable names of the transparency displays: "opaque", "translucent".
[[nodiscard]] std::string_view trimDisplayName(TrimDisplay display);
[[nodiscard]] std::optional<TrimDisplay> parseTrimDisplay(std::string_view name);

} // namespace trimlab
