#include "ui/render_panel/method_group.h"

#include "render/mfr/method_parameter_table.h"
#include "ui/common/parameter_form.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStandardItemModel>

namespace trimlab::ui {

namespace {

QString methodKey(const render::MethodInfo& info)
{
    return QString::fromLatin1(info.id.data(), qsizetype(info.id.size()));
}

QString megabytesText(std::size_t bytes)
{
    return QString::number(double(bytes) / (1024.0 * 1024.0), 'f', 1);
}

} // namespace

QString methodDisplayName(const render::MethodInfo& info)
{
    return QString::fromUtf8(info.displayName.data(), qsizetype(info.displayName.size()));
}

QString methodToolTip(const render::MethodInfo& info)
{
    QString text = info.bounded
                       ? MethodGroup::tr("Capacity-bounded: keeps at most k fragments per pixel. Deeper pixels "
                                         "overflow; where the trim point was lost they are unresolved (magenta).")
                       : MethodGroup::tr("Unbounded: captures every fragment of the kept span, so it never "
                                         "overflows; its memory or its passes grow with the scene's depth.");
    if (info.usesK)
        text += MethodGroup::tr("\nUses k (fragments per pixel).");
    if (info.usesSharedCounters)
        text += MethodGroup::tr("\nUses S (shared counters of the memory referencing).");
    return text;
}

MethodGroup::MethodGroup(QWidget* parent) : QGroupBox(tr("Multi-fragment method"), parent)
{
    setObjectName(QStringLiteral("methodGroup"));
    auto* form = new QFormLayout(this);
    m_method = new QComboBox(this);
    m_method->setObjectName(QStringLiteral("methodComboBox"));
    addMethodItems();
    form->addRow(tr("Method"), m_method);
    // Each spin box reallocates on Enter, not on every digit.
    m_k = parameterSpinBox(render::method_parameters::kK, "kSpinBox", this);
    m_k->setKeyboardTracking(false);
    form->addRow(tr("k"), m_k);
    m_sharedCounters = parameterSpinBox(render::method_parameters::kSharedCounters, "sharedCountersSpinBox", this);
    m_sharedCounters->setKeyboardTracking(false);
    form->addRow(tr("Shared counters S"), m_sharedCounters);
    m_budget = parameterSpinBox(render::method_parameters::kMemoryBudget, "memoryBudgetSpinBox", this);
    m_budget->setKeyboardTracking(false);
    form->addRow(tr("Memory budget"), m_budget);
    m_memory = new QLabel(this);
    m_memory->setObjectName(QStringLiteral("kMemoryLabel"));
    m_memory->setToolTip(tr("GPU memory the method would hold at the view's size (before the scene and the "
                            "render target)"));
    form->addRow(tr("Memory"), m_memory);
    connect(m_method, &QComboBox::currentIndexChanged, this, [this] {
        updateEnabledParameters();
        emit changed();
    });
    connect(m_k, &QSpinBox::valueChanged, this, &MethodGroup::changed);
    connect(m_sharedCounters, &QSpinBox::valueChanged, this, &MethodGroup::changed);
    connect(m_budget, &QSpinBox::valueChanged, this, &MethodGroup::changed);
    updateEnabledParameters();
}

void MethodGroup::addMethodItems()
{
    for (const render::MethodInfo& info : render::fragmentMethods()) {
        m_method->addItem(methodDisplayName(info), methodKey(info));
        m_method->setItemData(m_method->count() - 1, methodToolTip(info), Qt::ToolTipRole);
    }
    m_unavailable.assign(std::size_t(m_method->count()), QString());
}

void MethodGroup::setUnavailableMethods(const std::function<std::optional<QString>(const render::MethodInfo&)>& why)
{
    auto* model = qobject_cast<QStandardItemModel*>(m_method->model());
    for (int i = 0; i < m_method->count(); ++i) {
        const auto kind = render::parseFragmentMethod(m_method->itemData(i).toString().toStdString());
        if (!kind)
            continue;
        const render::MethodInfo& info = render::methodInfo(*kind);
        const std::optional<QString> reason = why(info);
        m_unavailable[std::size_t(i)] = reason.value_or(QString());
        if (QStandardItem* item = model ? model->item(i) : nullptr)
            item->setEnabled(!reason);
        m_method->setItemData(i, reason ? tr("Unavailable: %1").arg(*reason) : methodToolTip(info), Qt::ToolTipRole);
    }
}

QString MethodGroup::unavailableReason(render::FragmentMethodKind method) const
{
    for (int i = 0; i < m_method->count(); ++i)
        if (render::parseFragmentMethod(m_method->itemData(i).toString().toStdString()) == method)
            return m_unavailable[std::size_t(i)];
    return {};
}

std::optional<render::FragmentMethodKind> MethodGroup::firstAvailableMethod() const
{
    for (int i = 0; i < m_method->count(); ++i)
        if (m_unavailable[std::size_t(i)].isEmpty())
            return render::parseFragmentMethod(m_method->itemData(i).toString().toStdString());
    return std::nullopt;
}

void MethodGroup::setChoices(render::FragmentMethodKind method, int k, int sharedCounters)
{
    const QSignalBlocker methodBlocker(m_method);
    const QSignalBlocker kBlocker(m_k);
    const QSignalBlocker sharedBlocker(m_sharedCounters);
    int index = 0;
    for (int i = 0; i < m_method->count(); ++i)
        if (render::parseFragmentMethod(m_method->itemData(i).toString().toStdString()) == method)
            index = i;
    m_method->setCurrentIndex(index);
    m_k->setValue(k);
    m_sharedCounters->setValue(sharedCounters);
    updateEnabledParameters();
}

render::FragmentMethodKind MethodGroup::method() const
{
    const auto kind = render::parseFragmentMethod(m_method->currentData().toString().toStdString());
    return kind.value_or(render::fragmentMethods().front().kind);
}

int MethodGroup::k() const
{
    return m_k->value();
}

int MethodGroup::sharedCounters() const
{
    return m_sharedCounters->value();
}

void MethodGroup::setMemoryBudgetMegabytes(int megabytes)
{
    const QSignalBlocker blocker(m_budget);
    m_budget->setValue(megabytes);
}

int MethodGroup::memoryBudgetMegabytes() const
{
    return m_budget->value();
}

void MethodGroup::setMemoryEstimate(const MemoryEstimate& estimate)
{
    if (!estimate.available) {
        m_memory->setText(QString());
        return;
    }
    const QString size = QStringLiteral("%1×%2").arg(estimate.pixelSize.width()).arg(estimate.pixelSize.height());
    m_memory->setText(estimate.bytes ? tr("≈ %1 MB at %2").arg(megabytesText(*estimate.bytes), size)
                                     : tr("depends on the scene (allocated per frame at %1)").arg(size));
}

void MethodGroup::updateEnabledParameters()
{
    const render::MethodInfo& info = render::methodInfo(method());
    m_k->setEnabled(info.usesK);
    m_sharedCounters->setEnabled(info.usesSharedCounters);
    m_method->setToolTip(methodToolTip(info));
}

} // namespace trimlab::ui
