#include "ui/common/form_controls.h"

#include <QCheckBox>
#include <QComboBox>

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

} // namespace trimlab::ui
