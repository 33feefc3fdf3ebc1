#include "ui/animation/segmentation_settings_form.h"

#include "ui/common/form_controls.h"
#include "ui/common/parameter_form.h"

#include <QComboBox>
#include <QFormLayout>
#include <QSignalBlocker>
#include <QSpinBox>

namespace trimlab::ui {

SegmentationSettingsForm::SegmentationSettingsForm(QWidget* parent) : QWidget(parent)
{
    using namespace segmentation_parameters;
    m_feature = parameterComboBox(kFeature, "featureComboBox");
    m_reference = parameterComboBox(kReference, "referenceComboBox");
    m_method = parameterComboBox(kMethod, "clusteringComboBox");
    m_clusters = parameterSpinBox(kClusters, "clustersSpinBox");
    m_threads = parameterSpinBox(kThreads, "threadsSpinBox");
    m_mode = parameterComboBox(kMode, "modeComboBox");

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
