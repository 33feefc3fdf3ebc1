#include "ui/skinning/skinning_settings_form.h"

#include "ui/common/form_controls.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>

namespace trimlab::ui {

namespace {
// The method box's data for the rigid-joint fit (the other items hold a SkinningMethod).
constexpr int kFitExported = 100;
} // namespace

SkinningSettingsForm::SkinningSettingsForm(QWidget* parent) : QWidget(parent)
{
    m_boneSource = namedComboBox("skinningBoneSourceComboBox",
                                 {{tr("From the segmentation"), int(BoneSource::Segmentation)},
                                  {tr("Given count"), int(BoneSource::GivenCount)}},
                                 tr("One bone per segment of the segmentation shown, or the animation segmented anew "
                                    "into exactly the given number of segments"));
    m_boneCount = new QSpinBox;
    m_boneCount->setObjectName(QStringLiteral("skinningBoneCountSpinBox"));
    m_boneCount->setRange(1, SkinningChoices::kMaxBones);
    m_boneCount->setToolTip(tr("B: the bones to fit (the Segmentation panel's feature and clustering are used)"));
    m_bones = new QLabel;
    m_bones->setObjectName(QStringLiteral("skinningBoneCountLabel"));
    m_bones->setWordWrap(true);
    m_bones->setToolTip(tr("One proxy bone per segment of the segmentation shown in the Segmentation panel "
                           "(its h included); weights blend across segment borders"));
    m_method = namedComboBox("skinningMethodComboBox",
                             {{tr("Rigid joints (glTF skin)"), kFitExported},
                              {tr("LBS (affine bones)"), int(SkinningMethod::Lbs)},
                              {tr("DQS (rigid bones)"), int(SkinningMethod::Dqs)}},
                             tr("Rigid joints blended linearly, fitted together with the weights and rest pose: "
                                "exactly what a glTF skin plays, so the exported file has the lowest error. Or "
                                "linear blend skinning with affine bone transforms, or dual quaternion skinning with "
                                "rigid ones (thesis chapter 4)"));
    m_chain = namedComboBox("skinningChainComboBox",
                            {{tr("Pose to pose (p2p)"), int(SkinningChain::PoseToPose)},
                             {tr("Rest to pose (classical)"), int(SkinningChain::RestToPose)}},
                            tr("p2p-skinning fits each pose from the pose before it; the classical fit maps the rest "
                               "pose to every pose"));
    m_weightCorrections = namedCheckBox(tr("Weight corrections"), "weightCorrectionsCheckBox",
                                        tr("Re-estimate the weights from the fitted transforms and refit (rigid joints "
                                           "and rest-to-pose LBS: alternated with the fit until the error stops "
                                           "falling; otherwise once, kept only when E_RMS does not rise)"));
    m_vertexCorrections = namedCheckBox(tr("Vertex corrections"), "vertexCorrectionsCheckBox",
                                        tr("Move the rest-pose vertices to lower the error (alternated like the weight "
                                           "corrections, or once, kept only when E_RMS does not rise)"));
    m_influences = new QSpinBox;
    m_influences->setObjectName(QStringLiteral("skinningInfluencesSpinBox"));
    m_influences->setRange(1, int(kMaxInfluences));
    m_influences->setToolTip(tr("Bones per vertex when the weights are re-solved (rigid joints, or rest-to-pose LBS "
                                "with corrections). 4 plays in every engine; 5-8 lower the error on cloth-like parts "
                                "and are written as JOINTS_1/WEIGHTS_1, which not every viewer reads"));
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
    connect(this, &SkinningSettingsForm::changed, this, &SkinningSettingsForm::updateInfluencesEnabled);
    for (QCheckBox* box : {m_weightCorrections, m_vertexCorrections})
        connect(box, &QCheckBox::toggled, this, &SkinningSettingsForm::changed);
    setChoices(SkinningChoices{});
    setSegmentCount(0);
}

void SkinningSettingsForm::setChoices(const SkinningChoices& choices)
{
    const QSignalBlocker b1(m_method), b2(m_chain), b3(m_weightCorrections), b4(m_vertexCorrections),
        b5(m_boneSource), b6(m_boneCount), b7(m_influences);
    selectItemWithData(m_boneSource, int(choices.boneSource));
    m_boneCount->setValue(choices.boneCount);
    selectItemWithData(m_method, choices.fitExported ? kFitExported : int(choices.method));
    m_chosenChain = choices.chain;
    m_weightCorrections->setChecked(choices.weightCorrections);
    m_vertexCorrections->setChecked(choices.vertexCorrections);
    m_influences->setValue(choices.influences);
    updateBoneCountEnabled();
    updateChainEnabled();
    updateInfluencesEnabled();
}

SkinningChoices SkinningSettingsForm::choices() const
{
    SkinningChoices choices;
    choices.boneSource = BoneSource(m_boneSource->currentData().toInt());
    choices.boneCount = m_boneCount->value();
    choices.fitExported = m_method->currentData().toInt() == kFitExported;
    choices.method = choices.fitExported ? SkinningMethod::Lbs : SkinningMethod(m_method->currentData().toInt());
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
    const bool fitExported = m_method->currentData().toInt() == kFitExported;
    const QSignalBlocker blocker(m_chain);
    selectItemWithData(m_chain, int(fitExported ? SkinningChain::RestToPose : m_chosenChain));
    m_chain->setEnabled(!fitExported);
}

// Only the fits that re-solve the weights can use more (or fewer) than the segmentation's 4.
void SkinningSettingsForm::updateInfluencesEnabled()
{
    m_influences->setEnabled(usesDecomposition(choices().fitOptions()));
}

void SkinningSettingsForm::updateBoneCountEnabled()
{
    m_boneCount->setEnabled(BoneSource(m_boneSource->currentData().toInt()) == BoneSource::GivenCount);
}

} // namespace trimlab::ui
