#pragma once
/// \file
/// The Timeline's second row: how the poses played are classified
/// (pose_history_choices.h) — "Static rule" or one of the dynamic rules, and against the
/// rest pose or the previous pose. The reference choice is disabled under the static rule,
/// where it means nothing.

#include "ui/animation/pose_history_choices.h"

#include <QWidget>

class QComboBox;
class QLabel;

namespace trimlab::ui {

class PoseHistoryBar : public QWidget {
    Q_OBJECT
public:
    explicit PoseHistoryBar(QWidget* parent = nullptr);

    /// Shows `choices` without emitting choicesChanged().
    void setChoices(const PoseHistoryChoices& choices);
    [[nodiscard]] PoseHistoryChoices choices() const;
    /// What the last frame cost, e.g. "12 sets, 1 characterized"; empty clears it.
    void setStatus(const QString& status);

signals:
    /// The user changed the rule or the reference.
    void choicesChanged();

private:
    void updateEnabled();

    QComboBox* m_rule = nullptr;
    QComboBox* m_reference = nullptr;
    QLabel* m_status = nullptr;
};

} // namespace trimlab::ui
