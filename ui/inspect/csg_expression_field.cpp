#include "ui/inspect/csg_expression_field.h"

#include "ui/common/form_controls.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace trimlab::ui {

std::optional<CsgExpression> csgExpressionForScene(const QString& text, int objectCount, QString* error)
{
    if (text.trimmed().isEmpty())
        return CsgExpression{};
    std::string reason;
    std::optional<CsgExpression> expression = parseCsgExpression(text.toStdString(), &reason);
    if (!expression) {
        if (error)
            *error = QString::fromStdString(reason);
        return std::nullopt;
    }
    const int largest = csgMaxObjectId(*expression);
    if (largest >= objectCount) {
        if (error)
            *error = objectCount == 0
                         ? QObject::tr("The scene has no objects.")
                         : QObject::tr("Object %1 does not exist: the scene has %2 object(s), ids 0 to %3.")
                               .arg(largest)
                               .arg(objectCount)
                               .arg(objectCount - 1);
        return std::nullopt;
    }
    return expression;
}

CsgExpressionField::CsgExpressionField(QWidget* parent) : QGroupBox(tr("CSG"), parent)
{
    setObjectName(QStringLiteral("csgGroup"));
    auto* layout = new QVBoxLayout(this);
    m_text = new QLineEdit(this);
    m_text->setObjectName(QStringLiteral("csgExpressionEdit"));
    m_text->setPlaceholderText(tr("e.g. 0 - 1 or 0 | (1 & 2); empty: no CSG"));
    m_text->setToolTip(tr("Object ids combined with | (union), & (intersection, binds tighter) and - (difference), "
                          "with parentheses. Each object is classified by its own rule; objects the expression "
                          "does not mention are not shown. Needs a buffer method (not peeling or two-pass)."));
    m_text->setClearButtonEnabled(true);
    layout->addWidget(m_text);
    m_error = noticeLabel(this, "csgErrorLabel", NoticeKind::Error);
    layout->addWidget(m_error);
    auto* buttons = new QHBoxLayout;
    buttons->setContentsMargins(0, 0, 0, 0);
    m_union = addBuildButton(tr("Union"), QStringLiteral("csgUnionButton"), tr("The union of the selected objects"),
                             CsgOperation::Union);
    m_intersection = addBuildButton(tr("Intersection"), QStringLiteral("csgIntersectionButton"),
                                    tr("The intersection of the selected objects"), CsgOperation::Intersection);
    m_difference = addBuildButton(tr("Difference"), QStringLiteral("csgDifferenceButton"),
                                  tr("The current object minus the other selected objects"), CsgOperation::Difference);
    buttons->addWidget(m_union);
    buttons->addWidget(m_intersection);
    buttons->addWidget(m_difference);
    buttons->addStretch();
    layout->addLayout(buttons);
    connect(m_text, &QLineEdit::textEdited, this, &CsgExpressionField::onTextEdited);
    connect(m_text, &QLineEdit::editingFinished, this, &CsgExpressionField::typingFinished);
    setSelection(0, -1);
}

QPushButton* CsgExpressionField::addBuildButton(const QString& text, const QString& objectName, const QString& toolTip,
                                                CsgOperation operation)
{
    auto* button = new QPushButton(text, this);
    button->setObjectName(objectName);
    button->setToolTip(toolTip + tr(" (select two or more objects in the table)"));
    connect(button, &QPushButton::clicked, this, [this, operation] { emit buildRequested(operation); });
    return button;
}

void CsgExpressionField::setObjectCount(int count)
{
    m_objectCount = count;
    QString error;
    if (!csgExpressionForScene(m_text->text(), m_objectCount, &error))
        showError(error);
    else
        showError({});
}

void CsgExpressionField::setExpression(const CsgExpression& expression)
{
    const std::optional<CsgExpression> shown = csgExpressionForScene(m_text->text(), m_objectCount, nullptr);
    if (!shown || *shown != expression) {
        const QSignalBlocker blocker(m_text);
        m_text->setText(QString::fromStdString(formatCsgExpression(expression)));
    }
    showError({});
}

void CsgExpressionField::setSelection(int count, int differenceFrom)
{
    for (QPushButton* button : {m_union, m_intersection, m_difference})
        button->setEnabled(count >= 2);
    const bool named = count >= 2 && differenceFrom >= 0;
    m_difference->setText(named ? tr("Difference: %1 − others").arg(differenceFrom) : tr("Difference"));
    m_difference->setToolTip(named ? tr("Object %1 (the current row) minus the other selected objects; make another "
                                        "selected row current to keep that one instead")
                                         .arg(differenceFrom)
                                   : tr("The current object minus the other selected objects"));
}

QString CsgExpressionField::errorText() const
{
    return m_error->text();
}

void CsgExpressionField::onTextEdited(const QString& text)
{
    QString error;
    const std::optional<CsgExpression> expression = csgExpressionForScene(text, m_objectCount, &error);
    showError(expression ? QString() : error);
    if (expression)
        emit expressionTyped(*expression);
}

void CsgExpressionField::showError(const QString& error)
{
    m_error->setText(error);
    m_error->setVisible(!error.isEmpty());
}

} // namespace trimlab::ui
