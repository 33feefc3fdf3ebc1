#include "ui/skinning/skinning_settings_form.h"

#include "ui/common/form_controls.h"
#include "ui/common/parameter_form.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>

namespace trimlab::ui {

using namespace skinning_parameters;

SkinningSettingsForm::SkinningSettingsForm(QWidget* parent) : QWidget(parent)
{
    m_boneSource = namedComboBox("skinningBoneSourceComboBox",
                                 {{tr("From the segmentation"), int(BoneSource::Segmentation)},
                                  {tr("Given count"), int(BoneSource::GivenCount)}},
                                 tr("One bone per segment of the segmentation shown, or the animation segmented anew "
                                    "into exactly the given number of segments"));
    m_boneCount = parameterSpinBox(kBones, "skinningBoneCountSpinBox");
    m_bones = new QLabel;
    m_bones->setObjectName(QStringLiteral("skinningBoneCountLabel"));
    m_bones->setWordWrap(true);
    m_bones->setToolTip(tr("One proxy bone per segment of the segmentation shown in the Segmentation panel "
                           "(its h included); weights blend across segment borders"));
    m_method = parameterComboBox(kFit, "skinningMethodComboBox");
    m_chain = parameterComboBox(kChain, "skinningChainComboBox");
    m_weightCorrections = parameterCheckBox(kWeightCorrections, tr("Weight corrections"), "weightCorrectionsCheckBox");
    m_vertexCorrections = parameterCheckBox(kVertexCorrections, tr("Vertex corrections"), "vertexCorrectionsCheckBox");
    m_influences = parameterSpinBox(kInfluences, "skinningInfluencesSpinBox");
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow(tr("Bones"), m_boneSource);
    form->addRow(tr("Bone count"), m_boneCount);
    form->addRow(QString(), m_bones);
    form->addRow(tr("Method"), m_method);
    form->addRow(tr("Chain"), m_chain);
    form->addRow(m_weightCorrections);
    form->addRow(m_vertexCorrections);
    form->addRow(tr("Influences"), m_influences);
    for (QComboBox* box : {m_boneSource, m_method, m_chain})
        connect(box, &QComboBox::currentIndexChanged, this, &SkinningSettingsForm::changed);
    connect(m_boneSource, &QComboBox::currentIndexChanged, this, &SkinningSettingsForm::updateBoneCountEnabled);
    connect(m_method, &QComboBox::currentIndexChanged, this, &SkinningSettingsForm::updateChainEnabled);
    connect(m_chain, &QComboBox::currentIndexChanged, this,
            [this] { m_chosenChain = SkinningChain(m_chain->currentData().toInt()); });
    connect(m_boneCount, &QSpinBox::valueChanged, this, &SkinningSettingsForm::changed);
    connect(m_influences, &QSpinBox::valueChanged, this, &SkinningSettingsForm::changed);
    for (QCheckBox* box : {m_weightCorrections, m_vertexCorrections})
        connect(box, &QCheckBox::toggled, this, &SkinningSettingsForm::changed);
    setChoices(SkinningChoices{});
    setSegmentCount(0);
}

void SkinningSettingsForm::setChoices(const SkinningChoices& choices)
{
    const QSignalBlocker b1(m_method), b2(m_chain), b3(m_weightCorrections), b4(m_vertexCorrections), b5(m_boneSource),
        b6(m_boneCount), b7(m_influences);
    selectItemWithData(m_boneSource, int(choices.boneSource));
    m_boneCount->setValue(choices.boneCount);
    SkinningFitOptions fit;
    fit.fitExported = choices.fitExported;
    fit.method = choices.method;
    selectItemWithData(m_method, int(skinningFitKind(fit)));
    m_chosenChain = choices.chain;
    m_weightCorrections->setChecked(choices.weightCorrections);
    m_vertexCorrections->setChecked(choices.vertexCorrections);
    m_influences->setValue(choices.influences);
    updateBoneCountEnabled();
    updateChainEnabled();
}

SkinningChoices SkinningSettingsForm::choices() const
{
    SkinningChoices choices;
    choices.boneSource = BoneSource(m_boneSource->currentData().toInt());
    choices.boneCount = m_boneCount->value();
    SkinningFitOptions fit;
    setSkinningFitKind(fit, SkinningFitKind(m_method->currentData().toInt()));
    choices.fitExported = fit.fitExported;
    choices.method = fit.method;
    choices.chain = m_chosenChain;
    choices.weightCorrections = m_weightCorrections->isChecked();
    choices.vertexCorrections = m_vertexCorrections->isChecked();
    choices.influences = m_influences->value();
    return choices;
}

void SkinningSettingsForm::setSegmentCount(std::size_t count)
{
    m_bones->setText(count == 0 ? tr("The segmentation shown: none yet")
                                : tr("The segmentation shown: %1 segments").arg(count));
}

// The rigid-joint fit always maps the rest pose to each pose (nothing to drift): the chain
// box shows that and is disabled; LBS and DQS get back the chain last chosen for them.
void SkinningSettingsForm::updateChainEnabled()
{
    const bool fitExported = SkinningFitKind(m_method->currentData().toInt()) == SkinningFitKind::Rigid;
    const QSignalBlocker blocker(m_chain);
    selectItemWithData(m_chain, int(fitExported ? SkinningChain::RestToPose : m_chosenChain));
    m_chain->setEnabled(!fitExported);
}

void SkinningSettingsForm::updateBoneCountEnabled()
{
    m_boneCount->setEnabled(BoneSource(m_boneSource->currentData().toInt()) == BoneSource::GivenCount);
}

} // namespace trimlab::ui
