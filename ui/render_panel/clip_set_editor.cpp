#include "ui/render_panel/clip_set_editor.h"

#include "ui/render_panel/clip_plane_editor.h"

#include <glm/geometric.hpp>

#include <QButtonGroup>
#include <QCheckBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <cmath>

namespace trimlab::ui {

namespace {

QString number(double value)
{
    // A minus sign, not a hyphen; "-0" reads as 0.
    const QString text = QString::number(value == 0.0 ? 0.0 : value, 'g', 4);
    return text.startsWith(QLatin1Char('-')) ? QChar(0x2212) + text.mid(1) : text;
}

/// "x ≥ −1.2" for axis-aligned planes, "(0.6, 0, 0.8)·x ≥ 0.25" otherwise: the kept side.
QString equationText(const ClipPlane& plane)
{
    const glm::dvec3& n = plane.normal;
    const char* axes[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
        const double a = n[axis];
        const bool alone = a != 0.0 && n[(axis + 1) % 3] == 0.0 && n[(axis + 2) % 3] == 0.0;
        if (alone) // a·x + offset >= 0  <=>  x >= −offset / a (a > 0), x <= −offset / a (a < 0)
            return QStringLiteral("%1 %2 %3")
                .arg(QLatin1String(axes[axis]), a > 0.0 ? QStringLiteral("≥") : QStringLiteral("≤"),
                     number(-plane.offset / a));
    }
    return QStringLiteral("(%1, %2, %3)·x ≥ %4").arg(number(n.x), number(n.y), number(n.z), number(-plane.offset));
}

} // namespace

ClipSetEditor::ClipSetEditor(QWidget* parent) : QGroupBox(tr("Clipping planes"), parent)
{
    setObjectName(QStringLiteral("clipSetGroup"));
    setToolTip(tr("Up to %1 planes at once, e.g. a box: the scene is kept where every enabled plane keeps it. The "
                  "winding index is counted exactly, so the trimmed interior stays correct behind every cut.")
                   .arg(kMaxClipPlanes));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(createPlaneRows());
    layout->addWidget(createButtonRow());
    m_editor = new ClipPlaneEditor(this);
    layout->addWidget(m_editor);
    connect(m_editor, &ClipPlaneEditor::planeChanged, this, &ClipSetEditor::onEditorChanged);
    connect(m_editor, &ClipPlaneEditor::viewDirectionRequested, this, &ClipSetEditor::viewDirectionRequested);
    selectPlane(0);
}

QWidget* ClipSetEditor::createPlaneRows()
{
    auto* rows = new QWidget(this);
    auto* grid = new QGridLayout(rows);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setVerticalSpacing(1);
    auto* picks = new QButtonGroup(rows);
    for (int i = 0; i < kMaxClipPlanes; ++i) {
        const auto slot = std::size_t(i);
        m_enabled[slot] = new QCheckBox(tr("Plane %1").arg(i + 1), rows);
        m_enabled[slot]->setObjectName(QStringLiteral("clipPlaneEnabled%1").arg(i));
        m_enabled[slot]->setToolTip(tr("Cut with plane %1").arg(i + 1));
        m_pick[slot] = new QRadioButton(tr("Edit"), rows);
        m_pick[slot]->setObjectName(QStringLiteral("clipPlaneSelect%1").arg(i));
        m_pick[slot]->setToolTip(tr("Edit plane %1 below").arg(i + 1));
        picks->addButton(m_pick[slot], i);
        m_equation[slot] = new QLabel(rows);
        m_equation[slot]->setObjectName(QStringLiteral("clipPlaneEquation%1").arg(i));
        grid->addWidget(m_enabled[slot], i, 0);
        grid->addWidget(m_equation[slot], i, 1);
        grid->addWidget(m_pick[slot], i, 2);
        connect(m_enabled[slot], &QCheckBox::toggled, this, [this, i](bool on) { onRowToggled(i, on); });
    }
    grid->setColumnStretch(1, 1);
    connect(picks, &QButtonGroup::idClicked, this, &ClipSetEditor::selectPlane);
    return rows;
}

QWidget* ClipSetEditor::createButtonRow()
{
    auto* row = new QWidget(this);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* box = new QPushButton(tr("Box"), row);
    box->setObjectName(QStringLiteral("clipBoxButton"));
    box->setToolTip(tr("Six planes around the scene's bounds; move each plane's offset to shrink the box"));
    connect(box, &QPushButton::clicked, this, &ClipSetEditor::setBoxAroundScene);
    auto* none = new QPushButton(tr("None"), row);
    none->setObjectName(QStringLiteral("clipNoneButton"));
    none->setToolTip(tr("Disable every clipping plane"));
    connect(none, &QPushButton::clicked, this, &ClipSetEditor::disableAll);
    layout->addWidget(box);
    layout->addWidget(none);
    layout->addStretch();
    return row;
}

void ClipSetEditor::setClipSet(const ClipSet& set)
{
    m_planes = set;
    const QSignalBlocker blocker(m_editor);
    m_editor->setPlane(m_planes.planes[std::size_t(m_selected)]);
    refreshRows();
}

void ClipSetEditor::setSceneBounds(const Bounds& bounds)
{
    m_bounds = bounds;
    m_editor->setSceneBounds(bounds);
}

void ClipSetEditor::selectPlane(int index)
{
    if (index < 0 || index >= kMaxClipPlanes)
        return;
    m_selected = index;
    {
        const QSignalBlocker blocker(m_editor);
        m_editor->setPlane(m_planes.planes[std::size_t(index)]);
    }
    m_editor->setTitle(tr("Plane %1").arg(index + 1));
    const QSignalBlocker pickBlocker(m_pick[std::size_t(index)]);
    m_pick[std::size_t(index)]->setChecked(true);
}

void ClipSetEditor::setNormalThroughCenter(const glm::dvec3& normal)
{
    m_editor->setNormalThroughCenter(normal); // emits planeChanged -> onEditorChanged
}

void ClipSetEditor::setBoxAroundScene()
{
    if (!m_bounds.valid())
        return;
    const glm::dvec3 margin(kBoxMargin * glm::length(m_bounds.max - m_bounds.min));
    m_planes = ClipSet::box(m_bounds.min - margin, m_bounds.max + margin);
    selectPlane(0);
    refreshRows();
    emit clipSetChanged();
}

void ClipSetEditor::disableAll()
{
    for (ClipPlane& plane : m_planes.planes)
        plane.enabled = false;
    const QSignalBlocker blocker(m_editor);
    m_editor->setPlane(m_planes.planes[std::size_t(m_selected)]);
    refreshRows();
    emit clipSetChanged();
}

void ClipSetEditor::onEditorChanged()
{
    m_planes.planes[std::size_t(m_selected)] = m_editor->plane();
    refreshRows();
    emit clipSetChanged();
}

void ClipSetEditor::onRowToggled(int index, bool enabled)
{
    ClipPlane& plane = m_planes.planes[std::size_t(index)];
    plane.enabled = enabled && plane.normal != glm::dvec3(0.0);
    if (index == m_selected) {
        const QSignalBlocker blocker(m_editor);
        m_editor->setPlane(plane);
    }
    refreshRows();
    emit clipSetChanged();
}

void ClipSetEditor::refreshRows()
{
    for (int i = 0; i < kMaxClipPlanes; ++i) {
        const auto slot = std::size_t(i);
        const ClipPlane& plane = m_planes.planes[slot];
        const QSignalBlocker blocker(m_enabled[slot]);
        m_enabled[slot]->setChecked(plane.enabled);
        m_equation[slot]->setText(equationText(plane));
        m_equation[slot]->setEnabled(plane.enabled);
    }
}

} // namespace trimlab::ui
