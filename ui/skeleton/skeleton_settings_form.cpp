#include "ui/skeleton/skeleton_settings_form.h"

#include "ui/common/form_controls.h"
#include "ui/common/parameter_form.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QToolButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <memory>
#include <vector>

namespace trimlab::ui {

using namespace skeleton_parameters;

SkeletonSettingsForm::SkeletonSettingsForm(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(createSelectionGroup());
    layout->addWidget(createSolverSection());
    setChoices({});
    for (QDoubleSpinBox* box : findChildren<QDoubleSpinBox*>())
        connect(box, &QDoubleSpinBox::valueChanged, this, &SkeletonSettingsForm::changed);
    for (QSpinBox* box : findChildren<QSpinBox*>())
        connect(box, &QSpinBox::valueChanged, this, &SkeletonSettingsForm::changed);
    for (QComboBox* box : {m_ordering, m_solver, m_skinning})
        connect(box, &QComboBox::currentIndexChanged, this, &SkeletonSettingsForm::changed);
    connect(m_refine, &QCheckBox::toggled, this, &SkeletonSettingsForm::changed);
    connect(m_nodes, &QSpinBox::valueChanged, this, &SkeletonSettingsForm::nodesOrRootChanged);
    connect(m_root, &QSpinBox::valueChanged, this, &SkeletonSettingsForm::nodesOrRootChanged);
    connect(m_skinning, &QComboBox::currentIndexChanged, this, &SkeletonSettingsForm::skinningChanged);
}

// The contraction and simplification parameters are the solver's: folded away under one
// toggle (closed at first) so that Run follows the choices a user makes on every mesh.
QWidget* SkeletonSettingsForm::createSolverSection()
{
    auto* section = new QWidget;
    auto* toggle = new QToolButton;
    toggle->setObjectName(QStringLiteral("skeletonSolverToggle"));
    toggle->setText(tr("Solver settings (contraction, simplification)"));
    toggle->setCheckable(true);
    toggle->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    toggle->setArrowType(Qt::RightArrow);
    toggle->setAutoRaise(true);
    auto* groups = new QWidget;
    groups->setObjectName(QStringLiteral("skeletonSolverGroups"));
    auto* inner = new QVBoxLayout(groups);
    inner->setContentsMargins(0, 0, 0, 0);
    inner->addWidget(createContractionGroup());
    inner->addWidget(createSimplificationGroup());
    groups->setVisible(false);
    connect(toggle, &QToolButton::toggled, groups, [toggle, groups](bool open) {
        toggle->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
        groups->setVisible(open);
    });
    auto* layout = new QVBoxLayout(section);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(toggle);
    layout->addWidget(groups);
    return section;
}

QWidget* SkeletonSettingsForm::createContractionGroup()
{
    auto* group = new QGroupBox(tr("Contraction"));
    m_initialWeight = parameterDoubleSpinBox(kInitialContractionWeight, "skeletonInitialWeightSpinBox");
    m_growth = parameterDoubleSpinBox(kContractionGrowth, "skeletonGrowthSpinBox");
    m_maxContraction = parameterDoubleSpinBox(kMaxContractionWeight, "skeletonMaxContractionSpinBox");
    m_maxAttraction = parameterDoubleSpinBox(kMaxAttractionWeight, "skeletonMaxAttractionSpinBox");
    m_iterations = parameterSpinBox(kMaxIterations, "skeletonIterationsSpinBox");
    m_ordering = parameterComboBox(kOrdering, "skeletonOrderingComboBox");
    m_solver = parameterComboBox(kSolver, "skeletonSolverComboBox");
    auto* form = new QFormLayout(group);
    form->addRow(tr("Initial pull"), m_initialWeight);
    form->addRow(tr("Pull growth"), m_growth);
    form->addRow(tr("Strongest pull"), m_maxContraction);
    form->addRow(tr("Strongest hold"), m_maxAttraction);
    form->addRow(tr("Max iterations"), m_iterations);
    form->addRow(tr("Ordering"), m_ordering);
    form->addRow(tr("Solver"), m_solver);
    return group;
}

QWidget* SkeletonSettingsForm::createSimplificationGroup()
{
    auto* group = new QGroupBox(tr("Simplification and refinement"));
    m_delta = parameterDoubleSpinBox(kPreCollapseFraction, "skeletonDeltaSpinBox");
    m_shapeWeight = parameterDoubleSpinBox(kShapeWeight, "skeletonShapeWeightSpinBox");
    m_samplingWeight = parameterDoubleSpinBox(kSamplingWeight, "skeletonSamplingWeightSpinBox");
    m_refine = parameterCheckBox(kRefine, tr("Refine (centre the nodes)"), "skeletonRefineCheckBox");
    auto* form = new QFormLayout(group);
    form->addRow(tr("Short edges"), m_delta);
    form->addRow(tr("Shape weight"), m_shapeWeight);
    form->addRow(tr("Spacing weight"), m_samplingWeight);
    form->addRow(m_refine);
    return group;
}

QWidget* SkeletonSettingsForm::createSelectionGroup()
{
    auto* group = new QGroupBox(tr("Selection, weights and skinning"));
    m_nodes = parameterSpinBox(kTargetNodes, "skeletonNodesSpinBox");
    m_root = parameterSpinBox(kRootJoint, "skeletonRootSpinBox");
    m_heat = parameterDoubleSpinBox(kHeatConstant, "skeletonHeatConstantSpinBox");
    m_skinning = parameterComboBox(kPoseSkinning, "skeletonSkinningComboBox");
    auto* form = new QFormLayout(group);
    form->addRow(tr("Target nodes"), m_nodes);
    form->addRow(tr("Root joint"), m_root);
    form->addRow(tr("Weight spread"), m_heat);
    form->addRow(tr("Skinning"), m_skinning);
    return group;
}

void SkeletonSettingsForm::setChoices(const SkeletonChoices& c)
{
    const QList<QWidget*> widgets = findChildren<QWidget*>();
    std::vector<std::unique_ptr<QSignalBlocker>> blockers;
    for (QWidget* widget : widgets)
        blockers.push_back(std::make_unique<QSignalBlocker>(widget));
    const ContractionOptions& k = c.extraction.contraction;
    m_initialWeight->setValue(k.initialContractionWeight);
    m_growth->setValue(k.contractionGrowth);
    m_maxContraction->setValue(k.maxContractionWeight);
    m_maxAttraction->setValue(k.maxAttractionWeight);
    m_iterations->setValue(k.maxIterations);
    selectItemWithData(m_ordering, int(k.ordering));
    selectItemWithData(m_solver, int(k.backend));
    m_delta->setValue(c.extraction.simplification.preCollapseFraction);
    m_shapeWeight->setValue(c.extraction.simplification.shapeWeight);
    m_samplingWeight->setValue(c.extraction.simplification.samplingWeight);
    m_refine->setChecked(c.extraction.refine);
    m_nodes->setValue(c.extraction.targetNodes);
    m_root->setValue(c.extraction.rootJoint);
    m_heat->setValue(c.heatConstant);
    selectItemWithData(m_skinning, int(c.skinning));
}

void SkeletonSettingsForm::pickRootJoint(int joint)
{
    m_root->setValue(joint);
}

SkeletonChoices SkeletonSettingsForm::choices() const
{
    SkeletonChoices c;
    ContractionOptions& k = c.extraction.contraction;
    k.initialContractionWeight = m_initialWeight->value();
    k.contractionGrowth = m_growth->value();
    k.maxContractionWeight = m_maxContraction->value();
    k.maxAttractionWeight = m_maxAttraction->value();
    k.maxIterations = m_iterations->value();
    k.ordering = SparseOrdering(m_ordering->currentData().toInt());
    k.backend = SparseBackend(m_solver->currentData().toInt());
    c.extraction.simplification.preCollapseFraction = m_delta->value();
    c.extraction.simplification.shapeWeight = m_shapeWeight->value();
    c.extraction.simplification.samplingWeight = m_samplingWeight->value();
    c.extraction.refine = m_refine->isChecked();
    c.extraction.targetNodes = m_nodes->value();
    c.extraction.rootJoint = m_root->value();
    c.heatConstant = m_heat->value();
    c.skinning = SkinningMethod(m_skinning->currentData().toInt());
    return c;
}

} // namespace trimlab::ui
