#include "ui/surface/surface_panel.h"

#include "ui/common/count_text.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace trimlab::ui {

SurfacePanel::SurfacePanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("surfacePanel"));
    createControls();
    setSurface(Kind::None, QString(), 0.0);
}

void SurfacePanel::createControls()
{
    auto* layout = new QVBoxLayout(this);
    m_description = new QLabel(this);
    m_description->setObjectName(QStringLiteral("surfaceDescriptionLabel"));
    m_description->setWordWrap(true);
    layout->addWidget(m_description);
    layout->addWidget(createNurbsGroup());
    layout->addWidget(createSubdivisionGroup());
    m_showNet = new QCheckBox(tr("Show control net"), this);
    m_showNet->setObjectName(QStringLiteral("showControlNetCheckBox"));
    m_showNet->setToolTip(tr("Draw the control net (NURBS) or cage (subdivision) over the surface."));
    layout->addWidget(m_showNet);
    layout->addWidget(createSelectionGroup());
    auto* hint = new QLabel(tr("Control points (P): click picks, Shift+click adds or removes, drag moves the selection "
                               "in the view plane, Ctrl+drag along its normal; Alt+drag orbits."),
                            this);
    hint->setWordWrap(true);
    layout->addWidget(hint);
    layout->addStretch();
    connect(m_showNet, &QCheckBox::toggled, this, [this](bool on) {
        emit showNetToggled(on);
        emit choicesChanged();
    });
}

QGroupBox* SurfacePanel::createNurbsGroup()
{
    m_nurbsGroup = new QGroupBox(tr("NURBS"), this);
    auto* form = new QFormLayout(m_nurbsGroup);
    m_segmentsU = new QSpinBox(m_nurbsGroup);
    m_segmentsU->setObjectName(QStringLiteral("surfaceSegmentsUSpinBox"));
    m_segmentsV = new QSpinBox(m_nurbsGroup);
    m_segmentsV->setObjectName(QStringLiteral("surfaceSegmentsVSpinBox"));
    for (QSpinBox* box : {m_segmentsU, m_segmentsV}) {
        box->setRange(SurfaceChoices::kMinSegments, SurfaceChoices::kMaxSegments);
        box->setKeyboardTracking(false); // typing "64" must not rebuild at "6" first
        box->setToolTip(tr("Tessellation intervals across the parameter domain (more: finer mesh)."));
    }
    form->addRow(tr("Density u"), m_segmentsU);
    form->addRow(tr("Density v"), m_segmentsV);
    m_degree = new QSpinBox(m_nurbsGroup);
    m_degree->setObjectName(QStringLiteral("surfaceDegreeSpinBox"));
    m_degree->setRange(1, SurfaceChoices::kMaxPatchDegree);
    m_degree->setKeyboardTracking(false);
    m_degree->setToolTip(tr("Degree in u and v of a patch (the primitives' degrees are fixed by their exact "
                            "rational form)."));
    form->addRow(tr("Patch degree"), m_degree);
    for (QSpinBox* box : {m_segmentsU, m_segmentsV, m_degree})
        connect(box, &QSpinBox::valueChanged, this, [this] {
            emit parametersEdited();
            emit choicesChanged();
        });
    return m_nurbsGroup;
}

QGroupBox* SurfacePanel::createSubdivisionGroup()
{
    m_subdivisionGroup = new QGroupBox(tr("Subdivision"), this);
    auto* form = new QFormLayout(m_subdivisionGroup);
    m_scheme = new QComboBox(m_subdivisionGroup);
    m_scheme->setObjectName(QStringLiteral("surfaceSchemeComboBox"));
    m_scheme->addItem(tr("Catmull–Clark"), int(SubdivisionScheme::CatmullClark));
    m_scheme->addItem(tr("Loop (triangle cages)"), int(SubdivisionScheme::Loop));
    form->addRow(tr("Scheme"), m_scheme);
    m_level = new QSpinBox(m_subdivisionGroup);
    m_level->setObjectName(QStringLiteral("surfaceLevelSpinBox"));
    m_level->setRange(0, SubdivisionSurface::kMaxLevel);
    m_level->setKeyboardTracking(false);
    m_level->setToolTip(tr("Uniform refinement level: each level splits every face into four."));
    form->addRow(tr("Level"), m_level);
    m_mode = new QComboBox(m_subdivisionGroup);
    m_mode->setObjectName(QStringLiteral("surfaceModeComboBox"));
    m_mode->addItem(tr("Limit surface"), int(SubdivisionMode::Limit));
    m_mode->addItem(tr("Uniform refinement"), int(SubdivisionMode::Uniform));
    m_mode->setToolTip(tr("Limit: the refined vertices pushed onto the limit surface. Uniform: the refined cage."));
    form->addRow(tr("Positions"), m_mode);
    connect(m_level, &QSpinBox::valueChanged, this, [this] {
        emit parametersEdited();
        emit choicesChanged();
    });
    for (QComboBox* box : {m_scheme, m_mode})
        connect(box, &QComboBox::currentIndexChanged, this, [this] {
            emit parametersEdited();
            emit choicesChanged();
        });
    return m_subdivisionGroup;
}

QGroupBox* SurfacePanel::createSelectionGroup()
{
    auto* group = new QGroupBox(tr("Selection"), this);
    auto* layout = new QVBoxLayout(group);
    m_selection = new QLabel(group);
    m_selection->setObjectName(QStringLiteral("surfaceSelectionLabel"));
    layout->addWidget(m_selection);
    auto* row = new QHBoxLayout;
    m_normalStep = new QDoubleSpinBox(group);
    m_normalStep->setObjectName(QStringLiteral("surfaceNormalStepSpinBox"));
    m_normalStep->setToolTip(tr("Distance to move the selected points along their average surface normal "
                                "(negative: inwards)."));
    row->addWidget(m_normalStep, 1);
    m_moveAlongNormal = new QPushButton(tr("Move along normal"), group);
    m_moveAlongNormal->setObjectName(QStringLiteral("surfaceMoveAlongNormalButton"));
    row->addWidget(m_moveAlongNormal);
    layout->addLayout(row);
    connect(m_moveAlongNormal, &QPushButton::clicked, this,
            [this] { emit moveAlongNormalRequested(m_normalStep->value()); });
    connect(m_normalStep, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        if (m_radius > 0.0 && value != 0.0)
            m_normalStepFraction = std::min(std::abs(value) / m_radius, SurfaceChoices::kMaxNormalStepFraction);
        emit choicesChanged();
    });
    return group;
}

void SurfacePanel::setChoices(const SurfaceChoices& choices)
{
    const QSignalBlocker b1(m_segmentsU), b2(m_segmentsV), b3(m_degree), b4(m_scheme), b5(m_level), b6(m_mode),
        b7(m_showNet), b8(m_normalStep);
    m_segmentsU->setValue(choices.segmentsU);
    m_segmentsV->setValue(choices.segmentsV);
    m_degree->setValue(choices.patchDegree);
    m_scheme->setCurrentIndex(m_scheme->findData(int(choices.scheme)));
    m_level->setValue(choices.level);
    m_mode->setCurrentIndex(m_mode->findData(int(choices.mode)));
    m_showNet->setChecked(choices.showNet);
    m_normalStepFraction = choices.normalStepFraction;
    if (m_radius > 0.0)
        m_normalStep->setValue(m_normalStepFraction * m_radius);
}

SurfaceChoices SurfacePanel::choices() const
{
    SurfaceChoices choices;
    choices.segmentsU = m_segmentsU->value();
    choices.segmentsV = m_segmentsV->value();
    choices.patchDegree = m_degree->value();
    choices.scheme = SubdivisionScheme(m_scheme->currentData().toInt());
    choices.level = m_level->value();
    choices.mode = SubdivisionMode(m_mode->currentData().toInt());
    choices.showNet = m_showNet->isChecked();
    choices.normalStepFraction = m_normalStepFraction;
    return choices;
}

void SurfacePanel::setSurface(Kind kind, const QString& description, double boundingRadius)
{
    m_kind = kind;
    m_radius = boundingRadius > 0.0 && std::isfinite(boundingRadius) ? boundingRadius : 0.0;
    m_description->setText(kind == Kind::None ? tr("No editable surface. Create one with Create ▸ NURBS or "
                                                   "Create ▸ Subdivision Surface.")
                                              : description);
    if (m_radius > 0.0) {
        const QSignalBlocker blocker(m_normalStep);
        const int decimals = std::clamp(3 - int(std::floor(std::log10(m_radius * 0.01))), 2, 8);
        m_normalStep->setDecimals(decimals);
        m_normalStep->setRange(-SurfaceChoices::kMaxNormalStepFraction * m_radius,
                               SurfaceChoices::kMaxNormalStepFraction * m_radius);
        m_normalStep->setSingleStep(m_radius * 0.01);
        m_normalStep->setValue(m_normalStepFraction * m_radius);
    }
    updateEnabled();
}

void SurfacePanel::setSelectionCount(int count)
{
    m_selectionCount = std::max(count, 0);
    m_selection->setText(tr("%1 selected").arg(countOf(m_selectionCount, tr("control point"), tr("control points"))));
    updateEnabled();
}

void SurfacePanel::updateEnabled()
{
    const bool nurbs = m_kind == Kind::Nurbs || m_kind == Kind::NurbsPatch;
    m_nurbsGroup->setEnabled(nurbs);
    m_degree->setEnabled(m_kind == Kind::NurbsPatch);
    m_subdivisionGroup->setEnabled(m_kind == Kind::Subdivision);
    m_moveAlongNormal->setEnabled(m_kind != Kind::None && m_selectionCount > 0);
    m_normalStep->setEnabled(m_kind != Kind::None);
    if (m_selection->text().isEmpty())
        m_selection->setText(
            tr("%1 selected").arg(countOf(m_selectionCount, tr("control point"), tr("control points"))));
}

} // namespace trimlab::ui
