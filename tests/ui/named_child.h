#pragma once
/// \file
/// Finding the widgets of the main window by object name, as the widget tests do before
/// clicking or typing into them.

#include <QObject>
#include <QString>
#include <QtGlobal>

namespace trimlab::test {

/// The descendant of `parent` of type T named `name`, or nullptr with a warning naming it
/// (so that a renamed widget shows up in the test log, not only as a crash).
template <class T>
T* child(QObject* parent, const char* name)
{
    T* found = parent->findChild<T*>(QString::fromLatin1(name));
    if (!found)
        qWarning("no child named %s", name);
    return found;
}

} // namespace trimlab::test
