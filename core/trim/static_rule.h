#pragma once
/// \file
/// Static interior/exterior classification rules: pure functions of the winding index w
/// of a point (the index of its component of space). Thesis 8.1.1 gives parity, the
/// positive index and the alternating border; nonzero (|w| >= 1, what Blender's exact
/// self-union, SVG and PostScript keep), negative (w < 0, the pockets an outward-turned
/// dent encloses) and the threshold family w >= K / |w| >= K (where K or more layers
/// overlap) complete the set a CAD user compares against.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace trimlab {

/// A rule is a kind and, for the threshold kinds, K. A value type so that the threshold
/// travels with the rule through settings, projects, CSG operands and the GPU uniform.
class StaticRule {
public:
    enum class Kind : std::uint8_t {
        Parity,            ///< in iff w is odd ("alternating interior"); orientation invariant
        PositiveIndex,     ///< in iff w >= 1 (Heisserman's positive index rule)
        AlternatingBorder, ///< in iff ceil(w/2) mod 2 == 1, i.e. w mod 4 in {1, 2}
        Nonzero,           ///< in iff w != 0; orientation invariant
        Negative,          ///< in iff w < 0
        AtLeast,           ///< in iff w >= K (K >= 2; K = 1 is PositiveIndex)
        AbsAtLeast,        ///< in iff |w| >= K (K >= 2; K = 1 is Nonzero)
    };
    /// K ranges over [2, kMaxThreshold]: beyond it no real scene has that many layers, and
    /// the GPU code packs K above the kind's four bits of an int.
    static constexpr int kMaxThreshold = 1024;

    static const StaticRule Parity;
    static const StaticRule PositiveIndex;
    static const StaticRule AlternatingBorder;
    static const StaticRule Nonzero;
    static const StaticRule Negative;

    constexpr StaticRule() = default;
    /// w >= k; k <= 1 gives PositiveIndex (every k <= 1 keeps the same cells but w = 0..k-1,
    /// which no user asks for), k is clamped to kMaxThreshold.
    [[nodiscard]] static constexpr StaticRule atLeast(int k)
    {
        return k <= 1 ? PositiveIndex : StaticRule(Kind::AtLeast, k < kMaxThreshold ? k : kMaxThreshold);
    }
    /// |w| >= k; k <= 1 gives Nonzero, k is clamped to kMaxThreshold.
    [[nodiscard]] static constexpr StaticRule absAtLeast(int k)
    {
        return k <= 1 ? Nonzero : StaticRule(Kind::AbsAtLeast, k < kMaxThreshold ? k : kMaxThreshold);
    }

    [[nodiscard]] constexpr Kind kind() const { return m_kind; }
    /// K of the threshold kinds; 0 for the others.
    [[nodiscard]] constexpr int threshold() const { return m_threshold; }
    [[nodiscard]] constexpr bool isThreshold() const { return m_kind == Kind::AtLeast || m_kind == Kind::AbsAtLeast; }
    /// The rule keeps the same cells when every orientation is reversed (w -> -w).
    [[nodiscard]] bool orientationInvariant() const;

    friend constexpr bool operator==(StaticRule, StaticRule) = default;

private:
    constexpr explicit StaticRule(Kind kind, int threshold = 0) : m_kind(kind), m_threshold(threshold) {}

    Kind m_kind = Kind::Parity;
    int m_threshold = 0;
};

inline constexpr StaticRule StaticRule::Parity{Kind::Parity};
inline constexpr StaticRule StaticRule::PositiveIndex{Kind::PositiveIndex};
inline constexpr StaticRule StaticRule::AlternatingBorder{Kind::AlternatingBorder};
inline constexpr StaticRule StaticRule::Nonzero{Kind::Nonzero};
inline constexpr StaticRule StaticRule::Negative{Kind::Negative};

/// Classification of a point with winding index `w` under `rule` (true = interior).
[[nodiscard]] bool isInterior(StaticRule rule, int windingIndex);

/// A surface fragment separating index `wBefore` from `wAfter` belongs to the trim iff the
/// two sides classify differently.
[[nodiscard]] inline bool isTrimBoundary(StaticRule rule, int wBefore, int wAfter)
{
    return isInterior(rule, wBefore) != isInterior(rule, wAfter);
}

/// Stable command-line / settings / project names: "parity", "positive-index",
/// "alternating-border", "nonzero", "negative", "w>=K", "|w|>=K" (K written out).
[[nodiscard]] std::string ruleName(StaticRule rule);
/// Inverse of ruleName. Also accepts "positive", "alternating", and, for shells where
/// '>' and '|' need quoting, "at-least-K" and "abs-at-least-K". nullopt if unknown or K
/// is out of [1, kMaxThreshold].
[[nodiscard]] std::optional<StaticRule> parseStaticRule(std::string_view name);
/// The names a user may type, for error messages: "parity, positive-index, ...".
[[nodiscard]] std::string staticRuleNamesHelp();

/// The one int the shaders receive (shaders/common/static_rule.glsl): the kind in bits
/// 0-3, K above them.
[[nodiscard]] int shaderRuleCode(StaticRule rule);

} // namespace trimlab
