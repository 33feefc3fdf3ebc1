#pragma once
/// \file
/// The CSG part of the Scene panel: the expression in its documented text form
/// (core/trim/csg_expression.h: ids, | union, & intersection, - difference, parentheses),
/// validated at every keystroke — the parser's message, or the object an id names that
/// the scene lacks, shows under the field in red and the last valid expression stays
/// rendered — and buttons that build the union, intersection or difference of the
/// objects selected in the panel's table. An empty field means no CSG.

#include "core/trim/csg_expression.h"

#include <QGroupBox>
#include <QString>

#include <optional>

class QLabel;
class QLineEdit;
class QPushButton;

namespace trimlab::ui {

/// The expression `text` means for a scene of `objectCount` objects: an empty
/// expression for blank text, the parsed one, or nullopt with the reason in `error`
/// (the parser's message, or which id the scene lacks).
[[nodiscard]] std::optional<CsgExpression> csgExpressionForScene(const QString& text, int objectCount, QString* error);

class CsgExpressionField : public QGroupBox {
    Q_OBJECT
public:
    explicit CsgExpressionField(QWidget* parent = nullptr);

    /// The scene's object count, for validating ids.
    void setObjectCount(int count);
    /// Shows `expression` without emitting anything (kept as typed when the field already
    /// means it).
    void setExpression(const CsgExpression& expression);
    /// Enables the build buttons (they need two or more selected objects); the Difference
    /// button names the object it keeps, `differenceFrom` (−1: none), so that the user
    /// sees which object the others are subtracted from before clicking.
    void setSelection(int count, int differenceFrom);
    [[nodiscard]] QLineEdit* lineEdit() const { return m_text; }
    /// The message under the field ("" while the text is valid).
    [[nodiscard]] QString errorText() const;

signals:
    /// The user typed a valid expression (an empty one: CSG off).
    void expressionTyped(const trimlab::CsgExpression& expression);
    /// Return or focus out: the typed expression is complete.
    void typingFinished();
    /// A build button was pressed.
    void buildRequested(trimlab::CsgOperation operation);

private:
    QPushButton* addBuildButton(const QString& text, const QString& objectName, const QString& toolTip,
                                CsgOperation operation);
    void onTextEdited(const QString& text);
    void showError(const QString& error);

    QLineEdit* m_text = nullptr;
    QLabel* m_error = nullptr;
    QPushButton* m_union = nullptr;
    QPushButton* m_intersection = nullptr;
    QPushButton* m_difference = nullptr;
    int m_objectCount = 0;
};

} // namespace trimlab::ui
