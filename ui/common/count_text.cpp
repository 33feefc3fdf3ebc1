#include "ui/common/count_text.h"

#include <QLocale>

namespace trimlab::ui {

QString countOf(long long count, const QString& one, const QString& many)
{
    return QStringLiteral("%1 %2").arg(QLocale().toString(count), count == 1 ? one : many);
}

} // namespace trimlab::ui
