#pragma once
/// \file
/// `trimlab info FILE|demo:NAME`: the validation report of every object (counts,
/// bounding box, components, genus, defects with their first elements, and whether the
/// trim modes are available).

#include <QStringList>

namespace trimlab::app {

/// Runs the verb on the arguments after "info"; returns the exit code (0 success,
/// 1 unreadable or malformed input, 2 bad arguments).
int runInfoVerb(int argc, char** argv, const QStringList& arguments);

} // namespace trimlab::app
