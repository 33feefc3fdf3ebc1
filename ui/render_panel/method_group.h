#pragma once
/// \file
/// The "Multi-fragment method" group of the Render panel: a combo box of every method of
/// render::fragmentMethods() (tooltips say whether it is capacity-bounded and which
/// parameters it uses), k (enabled when the method uses it), S shared counters (enabled
/// when the method uses them), the user's GPU memory budget (0: none; a method that would
/// exceed it makes the view fall back to a leaner one, render/memory_fallback.h) and the
/// GPU memory estimate at the current frame size.
/// Methods appear as the render layer lists them; nothing here names a method.

#include "ui/viewport/memory_estimate.h"
#include "render/mfr/fragment_method.h"

#include <QGroupBox>

#include <functional>
#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QSpinBox;

namespace trimlab::ui {

class MethodGroup : public QGroupBox {
    Q_OBJECT
public:
    explicit MethodGroup(QWidget* parent = nullptr);

    /// Shows the choices without emitting changed(). An unknown method selects the first.
    void setChoices(render::FragmentMethodKind method, int k, int sharedCounters);
    [[nodiscard]] render::FragmentMethodKind method() const;
    [[nodiscard]] int k() const;
    [[nodiscard]] int sharedCounters() const;
    /// Shows the budget (MB, 0 = none) without emitting changed().
    void setMemoryBudgetMegabytes(int megabytes);
    [[nodiscard]] int memoryBudgetMegabytes() const;
    /// Disables the methods `why` gives a reason for, with the reason as their tooltip
    /// (the others get methodToolTip()). The current choice stays selected even when
    /// disabled; the caller moves it (RenderWorkspace::apply).
    void setUnavailableMethods(const std::function<std::optional<QString>(const render::MethodInfo&)>& why);
    /// Whether the item of `method` is enabled, and the reason it is not ("" when it is).
    [[nodiscard]] QString unavailableReason(render::FragmentMethodKind method) const;
    /// The first method whose item is enabled, in the list's order (nullopt: none).
    [[nodiscard]] std::optional<render::FragmentMethodKind> firstAvailableMethod() const;
    /// Shows `estimate` ("≈ 12.0 MB at 1024×768", "depends on the scene", or nothing).
    void setMemoryEstimate(const MemoryEstimate& estimate);

signals:
    /// The user changed the method, k or S.
    void changed();

private:
    void addMethodItems();
    void updateEnabledParameters();

    QComboBox* m_method = nullptr;
    QSpinBox* m_k = nullptr;
    QSpinBox* m_sharedCounters = nullptr;
    QSpinBox* m_budget = nullptr;
    QLabel* m_memory = nullptr;
    std::vector<QString> m_unavailable; ///< per item: why it is disabled, "" when it is not
};

/// The tooltip of a method: bounded or not, and what its parameters do.
[[nodiscard]] QString methodToolTip(const render::MethodInfo& info);
/// The method's display name as a QString.
[[nodiscard]] QString methodDisplayName(const render::MethodInfo& info);

} // namespace trimlab::ui
