#include "ui/common/form_controls.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>

namespace trimlab::ui {

QComboBox* namedComboBox(const char* name, const QList<std::pair<QString, int>>& items, const QString& toolTip)
{
    auto* box = new QComboBox;
    box->setObjectName(QString::fromLatin1(name));
    for (const auto& [text, value] : items)
        box->addItem(text, value);
    box->setToolTip(toolTip);
    return box;
}

void selectItemWithData(QComboBox* box, int value)
{
    const int index = box->findData(value);
    if (index >= 0)
        box->setCurrentIndex(index);
}

QCheckBox* namedCheckBox(const QString& text, const char* name, const QString& toolTip)
{
    auto* box = new QCheckBox(text);
    box->setObjectName(QString::fromLatin1(name));
    box->setToolTip(toolTip);
    return box;
}

QLabel* noticeLabel(QWidget* parent, const char* name, NoticeKind kind)
{
    auto* label = new QLabel(parent);
    label->setObjectName(QLatin1String(name));
    label->setWordWrap(true);
    label->setStyleSheet(kind == NoticeKind::Warning ? QStringLiteral("QLabel { color: #e67e22; }")
                                                     : QStringLiteral("QLabel { color: #c0392b; }"));
    label->setVisible(false);
    return label;
}

} // namespace trimlab::ui
