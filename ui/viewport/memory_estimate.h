#pragma once
/// \file
/// The GPU memory the chosen multi-fragment method would hold at the view's frame size,
/// as TrimRenderer::estimateMethodBytes answers it, for the method controls to show.

#include <QSize>

#include <cstddef>
#include <optional>

namespace trimlab::ui {

struct MemoryEstimate {
    bool available = false;           ///< false: no renderer (yet), nothing to show
    std::optional<std::size_t> bytes; ///< when available: nullopt means "depends on the scene"
    QSize pixelSize;                  ///< the frame size it is computed for (device pixels)
};

} // namespace trimlab::ui
