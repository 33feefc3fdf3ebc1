#include "app/display_available.h"

#include <cstdlib>
#include <initializer_list>

namespace trimlab::app {

bool displayAvailable()
{
    for (const char* variable : {"QT_QPA_PLATFORM", "DISPLAY", "WAYLAND_DISPLAY"}) {
        const char* value = std::getenv(variable);
        if (value && *value)
            return true;
    }
    return false;
}

} // namespace trimlab::app
