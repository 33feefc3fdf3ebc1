#include "ui/common/run_cancel_row.h"

#include <QHBoxLayout>
#include <QPushButton>
#include <QWidget>

namespace trimlab::ui {

QWidget* runCancelRow(QPushButton* run, QPushButton* cancel)
{
    auto* row = new QWidget;
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(run);
    layout->addWidget(cancel);
    return row;
}

} // namespace trimlab::ui
