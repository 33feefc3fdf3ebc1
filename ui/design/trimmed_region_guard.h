#pragma once
/// \file
/// The homogeneous confluent rule (thesis 8.1.1) on the design session's edits: under
/// that rule a brush drag whose region, or a control edit whose moved vertices, reach a
/// part of the last frame that was trimmed off is refused, with a message saying why.
/// The exact CPU check (core/design/trimmed_region_check.h) is built once per history
/// revision and base rule, so only the first edit after a change pays for it.

#include "core/design/brush_drag.h"
#include "core/design/trimmed_region_check.h"
#include "core/timeline/timeline.h"
#include "core/trim/static_rule.h"

#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace trimlab::ui {

class DesignSession;

class TrimmedRegionGuard {
    Q_DECLARE_TR_FUNCTIONS(TrimmedRegionGuard)
public:
    /// Why `drag` may not deform the last frame of `session` (whose base mesh is
    /// classified by `baseRule`), or nullopt when it may.
    [[nodiscard]] std::optional<QString> refuseDrag(const DesignSession& session, StaticRule baseRule,
                                                    const BrushDrag& drag);
    /// The same for a control edit, judged on exactly the vertices `frame` moves.
    [[nodiscard]] std::optional<QString> refuseControlEdit(const DesignSession& session, StaticRule baseRule,
                                                           const timeline::Frame& frame);
    /// Forgets the check (the session ended).
    void reset() { m_check.reset(); }
    /// Milliseconds the last check took (chain and rays), 0 before.
    [[nodiscard]] double lastCheckMilliseconds() const { return m_lastCheckMs; }

private:
    [[nodiscard]] std::optional<QString> refuseSample(const DesignSession& session, StaticRule baseRule,
                                                      const std::vector<std::uint32_t>& sample);

    std::unique_ptr<TrimmedRegionCheck> m_check; ///< for the last frame at m_checkRevision
    quint64 m_checkRevision = 0;
    StaticRule m_checkBaseRule = StaticRule::AlternatingBorder;
    double m_lastCheckMs = 0.0;
};

} // namespace trimlab::ui
