#pragma once
/// \file
/// How the static rules read in the GUI: a label and a tooltip per rule, and the rule
/// combo boxes of the Render panel (one entry per kind, K in a spin box beside it) and of
/// the Scene panel's object table (fixed entries, thresholds as presets). The item data
/// of every entry is the stable ruleName(), so settings and tests address entries by name.

#include "core/trim/static_rule.h"
#include "core/trim/trim_settings.h"

#include <QString>

#include <optional>

class QComboBox;

namespace trimlab::ui {

/// "Parity", "Nonzero", "w ≥ 3", "|w| ≥ 2", ...
[[nodiscard]] QString ruleLabel(StaticRule rule);
/// What classifies the solid of `settings`, for a sentence: "the alternating border rule"
/// or "the CSG 0 - 1".
[[nodiscard]] QString classificationLabel(const TrimSettings& settings);
/// One sentence saying which cells the rule keeps.
[[nodiscard]] QString ruleToolTip(StaticRule rule);

/// The combo box item data of a rule: ruleName(rule).
[[nodiscard]] QString ruleKey(StaticRule rule);

/// Fills `combo` with the rules a per-object choice offers: the five rules without K,
/// then w ≥ 2, w ≥ 3, |w| ≥ 2, |w| ≥ 3. Items carry ruleKey() as data and the tooltip.
void addRuleItems(QComboBox* combo);
/// Selects `rule` in a combo filled by addRuleItems(), first appending it when it is a
/// threshold the presets lack (a project or the command line can set any K).
void selectRule(QComboBox* combo, StaticRule rule);
/// The rule of the combo's current item; nullopt for an item without a rule ("Scene rule").
[[nodiscard]] std::optional<StaticRule> currentRule(const QComboBox* combo);

} // namespace trimlab::ui
