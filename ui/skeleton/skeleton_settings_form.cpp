#include "ui/skeleton/skeleton_settings_form.h"

#include "ui/common/form_controls.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <memory>
#include <vector>

namespace trimlab::ui {

namespace {

QDoubleSpinBox* realBox(const char* name, double lo, double hi, int decimals, double step, const QString& tip)
{
    auto* box = new QDoubleSpinBox;
    box->setObjectName(QString::fromLatin1(name));
    box->setRange(lo, hi);
    box->setDecimals(decimals);
    box->setSingleStep(step);
    box->setToolTip(tip);
    return box;
}

QSpinBox* intBox(const char* name, int lo, int hi, const QString& tip)
{
    auto* box = new QSpinBox;
    box->setObjectName(QString::fromLatin1(name));
    box->setRange(lo, hi);
    box->setToolTip(tip);
    return box;
}

} // namespace

SkeletonSettingsForm::SkeletonSettingsForm(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(createContractionGroup());
    layout->addWidget(createSimplificationGroup());
    layout->addWidget(createSelectionGroup());
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

QWidget* SkeletonSettingsForm::createContractionGroup()
{
    auto* group = new QGroupBox(tr("Contraction"));
    m_initialWeight = realBox("skeletonInitialWeightSpinBox", 0.0, 1000.0, 6, 0.001,
                              tr("How strongly the first iteration pulls the surface inward (the paper's W_L⁰); 0 = "
                                 "automatic (1: the paper's 10⁻³·√Ā spends its first ten iterations moving nothing)"));
    m_initialWeight->setSpecialValueText(tr("automatic (1)"));
    m_growth = realBox("skeletonGrowthSpinBox", 1.1, 10.0, 2, 0.1, tr("How much stronger the inward pull gets each iteration (the paper's s_L)"));
    m_maxContraction = realBox("skeletonMaxContractionSpinBox", 1.0, 1e6, 1, 100.0, tr("The strongest inward pull, as a multiple of the first (the cap of the paper's W_L; paper: 2048)"));
    m_maxAttraction = realBox("skeletonMaxAttractionSpinBox", 1.0, 1e7, 1, 1000.0, tr("How firmly vertices that stopped shrinking hold their place at most (the cap of the paper's W_H; "
                                 "paper: 10000)"));
    m_iterations = intBox("skeletonIterationsSpinBox", 1, 200, tr("At most this many contraction solves"));
    m_ordering = new QComboBox;
    m_ordering->setObjectName(QStringLiteral("skeletonOrderingComboBox"));
    m_ordering->addItem(QStringLiteral("AMD"), int(SparseOrdering::Amd));
    m_ordering->addItem(QStringLiteral("COLAMD"), int(SparseOrdering::Colamd));
    m_ordering->addItem(QStringLiteral("METIS"), int(SparseOrdering::Metis));
    m_ordering->setToolTip(tr("Fill-reducing ordering of the sparse factorizations (paper Table I)"));
    m_solver = new QComboBox;
    m_solver->setObjectName(QStringLiteral("skeletonSolverComboBox"));
    m_solver->addItem(QStringLiteral("CHOLMOD"), int(SparseBackend::Cholmod));
    m_solver->addItem(QStringLiteral("LDLT (Eigen)"), int(SparseBackend::EigenSimplicialLdlt));
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
    m_delta = realBox("skeletonDeltaSpinBox", 0.0, 0.1, 5, 0.0005,
                      tr("Edges shorter than this (a fraction of the bounding-box diagonal) collapse before the "
                         "simplification (the paper's δ); 0 disables it"));
    m_shapeWeight = realBox("skeletonShapeWeightSpinBox", 0.0, 1000.0, 3, 0.1, tr("How much keeping the curve's shape counts when collapsing edges (the paper's w_a)"));
    m_samplingWeight = realBox("skeletonSamplingWeightSpinBox", 0.0, 1000.0, 3, 0.05, tr("How much even spacing of the nodes counts when collapsing edges (the paper's w_b)"));
    m_refine = new QCheckBox(tr("Refine (centre the nodes)"));
    m_refine->setObjectName(QStringLiteral("skeletonRefineCheckBox"));
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
    m_nodes = intBox("skeletonNodesSpinBox", 20, 40, tr("Joints of the rig (paper: 20–40)"));
    m_root = intBox("skeletonRootSpinBox", -1, 39, tr("Root joint of the rig, or automatic"));
    m_root->setSpecialValueText(tr("automatic"));
    m_heat = realBox("skeletonHeatConstantSpinBox", 0.01, 100.0, 3, 0.05,
                     tr("How far each bone's influence spreads over the surface (the bone-heat constant c; "
                        "Pinocchio: 1; the paper: ≈ 0.22 mimics heat in the volume)"));
    m_skinning = new QComboBox;
    m_skinning->setObjectName(QStringLiteral("skeletonSkinningComboBox"));
    m_skinning->addItem(tr("Linear blend (LBS)"), int(SkinningMethod::Lbs));
    m_skinning->addItem(tr("Dual quaternion (DQS)"), int(SkinningMethod::Dqs));
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
