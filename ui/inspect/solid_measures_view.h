#pragma once
/// \file
/// The Scene panel's "Trimmed solid" group: the volume and surface area of the solid the
/// view shows under its rule or CSG expression, measured exactly (core/solid/
/// solid_measures.h, what Mesh Statistics' Measure and `trimlab trim` give) off the UI
/// thread while the group is on screen. It follows the view: a new frame with other
/// geometry, another pose or another classification cancels the measurement under way and,
/// once the view has rested for a moment (a brush stroke, playback, typing a CSG
/// expression), measures again — so the numbers always belong to the frame shown, or say
/// that they are being measured. The clipping planes do not change the solid measured (the
/// whole solid, as Export Trimmed Solid's default); Mesh Statistics gives the sections.
///
/// Measuring as the view changes can be turned off for meshes too large to re-trim often:
/// the choice is the user's and persists (key "scene/measureSolid").

#include "ui/inspect/solid_export.h"

#include "core/solid/solid_measures.h"

#include <QGroupBox>
#include <QString>

#include <memory>
#include <optional>

class QCheckBox;
class QLabel;
class QSettings;
class QTimer;

namespace trimlab::ui {

template <class T>
class BackgroundJob;

/// How the solid's measures read wherever they are shown (this group, Mesh Statistics):
/// "Trimmed solid under the nonzero rule (exact): volume …, surface area … (scene units)".
[[nodiscard]] QString solidMeasuresLine(const SolidMeasures& measures, const TrimSettings& settings);
/// A measure as the lines show it: six significant digits.
[[nodiscard]] QString measureNumber(double value);

class SolidMeasuresView : public QGroupBox {
    Q_OBJECT
public:
    /// `shown` says what the view shows (the window's Export Trimmed Solid source);
    /// `settings` keeps the on/off choice and must outlive the view.
    SolidMeasuresView(SolidExport::ShownSource shown, QSettings& settings, QWidget* parent = nullptr);
    ~SolidMeasuresView() override;

    /// The view may show something else, or the group came on screen (connect to every
    /// rendered frame and to its dock's visibilityChanged): when what would be measured
    /// changed, the measurement starts again after the rest delay. Nothing happens while
    /// the group is off screen (behind another tab) or measuring is off.
    void follow();

    [[nodiscard]] bool isMeasuring() const;
    [[nodiscard]] bool measuresAsShown() const;
    void setMeasuresAsShown(bool on);
    /// The group's text: the numbers, "Measuring…", why there is no solid, or a hint.
    [[nodiscard]] QString text() const;

signals:
    /// A measurement ended with numbers, a failure or a refusal shown.
    void measured();

protected:
    void showEvent(QShowEvent* event) override;

private:
    /// What decides the numbers: the scene shown and what classifies it.
    struct Subject {
        std::shared_ptr<const Scene> scene;
        bool trimEnabled = false;
        StaticRule rule;
        CsgSettings csg;
        QString refusal;
        friend bool operator==(const Subject&, const Subject&) = default;
    };
    [[nodiscard]] static Subject subjectOf(const SolidExport::Shown& shown);
    [[nodiscard]] bool onScreen() const;
    [[nodiscard]] BackgroundJob<SolidMeasures>* newJob();
    void startJob(const SolidExport::Shown& shown);
    void stopJob();
    void showResult(const SolidMeasures& measures);

    SolidExport::ShownSource m_shown;
    QSettings& m_settings;
    QCheckBox* m_enabled = nullptr;
    QLabel* m_text = nullptr;
    QTimer* m_rest = nullptr;
    BackgroundJob<SolidMeasures>* m_job = nullptr;
    TrimSettings m_measuredSettings;  ///< of the job under way or its result
    std::optional<Subject> m_subject; ///< measured, being measured or refused; none: to be asked
};

} // namespace trimlab::ui
