#include "ui/animation/segmentation_settings_form.h"

#include "ui/common/form_controls.h"

#include <QComboBox>
#include <QFormLayout>
#include <QSignalBlocker>
#include <QSpinBox>

namespace trimlab::ui {

SegmentationSettingsForm::SegmentationSettingsForm(QWidget* parent) : QWidget(parent)
{
    m_feature = namedComboBox("featureComboBox",
                              {{tr("Rotation angle"), int(FeatureKind::RotationAngle)},
                               {tr("Velocity"), int(FeatureKind::Velocity)},
                               {tr("Acceleration"), int(FeatureKind::Acceleration)}},
                              tr("What every pose is partitioned by: the rotation angle of the deformation gradients, or "
                                 "the vertex velocity or acceleration"));
    m_reference = namedComboBox("referenceComboBox",
                                {{tr("Rest pose"), int(ReferenceMode::Rest)}, {tr("Previous pose"), int(ReferenceMode::Previous)}},
                                tr("The pose rotation angles are measured against"));
    m_method = namedComboBox("clusteringComboBox",
                             {{tr("Region growing"), int(PartitionMethod::RegionGrowing)},
                              {tr("Hierarchical"), int(PartitionMethod::Hierarchical)}},
                             tr("Region growing is fast; hierarchical splitting gives better clusters"));
    m_clusters = new QSpinBox;
    m_clusters->setObjectName(QStringLiteral("clustersSpinBox"));
    m_clusters->setRange(1, SegmentationChoices::kMaxClusters);
    m_threads = new QSpinBox;
    m_threads->setObjectName(QStringLiteral("threadsSpinBox"));
    m_threads->setRange(0, SegmentationChoices::kMaxThreads);
    m_threads->setSpecialValueText(tr("all cores"));
    m_mode = namedComboBox("modeComboBox",
                           {{tr("Global"), int(SegmentationMode::Global)},
                            {tr("Real-time (stream poses)"), int(SegmentationMode::RealTime)},
                            {tr("Variable (per pose)"), int(SegmentationMode::Variable)}},
                           tr("Global: one segmentation of the whole animation. Real-time: built pose by pose as the "
                              "timeline plays. Variable: each pose joined with the next, shown per pose."));

    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow(tr("Feature"), m_feature);
    form->addRow(tr("Reference"), m_reference);
    form->addRow(tr("Clustering"), m_method);
    form->addRow(tr("Clusters per pose"), m_clusters);
    form->addRow(tr("Threads"), m_threads);
    form->addRow(tr("Mode"), m_mode);

    for (QComboBox* box : {m_feature, m_reference, m_method, m_mode})
        connect(box, &QComboBox::currentIndexChanged, this, &SegmentationSettingsForm::changed);
    for (QSpinBox* box : {m_clusters, m_threads})
        connect(box, &QSpinBox::valueChanged, this, &SegmentationSettingsForm::changed);
    connect(m_feature, &QComboBox::currentIndexChanged, this, &SegmentationSettingsForm::updateReferenceEnabled);
    setChoices(SegmentationChoices{});
}

void SegmentationSettingsForm::setChoices(const SegmentationChoices& choices)
{
    const QSignalBlocker b1(m_feature), b2(m_reference), b3(m_method), b4(m_clusters), b5(m_threads), b6(m_mode);
    selectItemWithData(m_feature, int(choices.feature));
    selectItemWithData(m_reference, int(choices.reference));
    selectItemWithData(m_method, int(choices.method));
    m_clusters->setValue(choices.clusters);
    m_threads->setValue(choices.threads);
    selectItemWithData(m_mode, int(choices.mode));
    updateReferenceEnabled();
}

SegmentationChoices SegmentationSettingsForm::applyTo(SegmentationChoices choices) const
{
    choices.feature = FeatureKind(m_feature->currentData().toInt());
    choices.reference = ReferenceMode(m_reference->currentData().toInt());
    choices.method = PartitionMethod(m_method->currentData().toInt());
    choices.clusters = m_clusters->value();
    choices.threads = m_threads->value();
    choices.mode = SegmentationMode(m_mode->currentData().toInt());
    return choices;
}

// Velocity and acceleration are differences of neighbouring frames: no reference pose.
void SegmentationSettingsForm::updateReferenceEnabled()
{
    m_reference->setEnabled(FeatureKind(m_feature->currentData().toInt()) == FeatureKind::RotationAngle);
}

} // namespace trimlab::ui
