#include "app/designed_frame.h"

#include "app/cli_messages.h"

#include "core/catalog/scene_source.h"
#include "core/catalog/surface_scenes.h"
#include "core/timeline/project_file.h"
#include "core/timeline/stroke_replay.h"
#include "core/timeline/stroke_script.h"

#include <filesystem>
#include <optional>
#include <stdexcept>

namespace trimlab::app {

namespace {

// The brush deforms one closed mesh; a scene of several objects has no single base.
const SceneObject& designedObject(const LoadedScene& loaded)
{
    if (loaded.scene.objects.size() != 1)
        throw std::invalid_argument(loaded.displayName + " has " + std::to_string(loaded.scene.objects.size()) +
                                    " objects; a stroke script deforms a single mesh.");
    if (!loaded.trimmable())
        throw std::invalid_argument(loaded.displayName + " cannot be designed: " + loaded.trimUnavailableReason());
    return loaded.scene.objects.front();
}

// Frame f of a design with `lastFrame` frames after the base, or why not.
int chosenFrame(const RenderOptions& options, int lastFrame, const std::string& displayName)
{
    const int frame = options.frame.value_or(lastFrame);
    if (frame > lastFrame)
        throw std::invalid_argument("--frame " + std::to_string(frame) + " is beyond the last frame of " + displayName +
                                    " (" + std::to_string(lastFrame) + ").");
    return frame;
}

DesignedFrame replayScript(const RenderOptions& options)
{
    const LoadedScene loaded = loadScene(options.sources.front());
    const SceneObject& object = designedObject(loaded);
    const std::filesystem::path scriptPath = options.script.toStdString();
    const timeline::StrokeScript script = timeline::loadStrokeScript(scriptPath);
    const std::string name = loaded.displayName + " + " + scriptPath.filename().string();
    // Checked before the replay, which may take a while.
    const int frame = chosenFrame(options, int(script.strokeCount()), name);
    TaskControl control;
    control.progress = [](const TaskProgress& progress) {
        if (progress.done == progress.total)
            printNote(QStringLiteral("replayed %1 strokes").arg(progress.total));
    };
    DesignedFrame design;
    design.timeline = timeline::replayStrokeScript(object.mesh, script, control, scriptPath.filename().string());
    design.frame = frame;
    design.model = object.modelMatrix;
    design.displayName = name;
    return design;
}

DesignedFrame loadProjectFile(const RenderOptions& options)
{
    const std::filesystem::path path = options.sources.front();
    timeline::Project project = timeline::readHistoryProject(path);
    DesignedFrame design;
    design.timeline = std::move(project.timeline);
    design.displayName = path.filename().string();
    design.frame = chosenFrame(options, design.timeline.frameCount() - 1, design.displayName);
    design.savedRule = project.extras.staticRule;
    if (project.extras.viewSettings)
        design.savedClassification = project.extras.viewSettings->classification;
    return design;
}

// A built-in surface demo with a history of control-point edits (surface_scenes.h).
std::optional<DesignedFrame> demoHistory(const RenderOptions& options)
{
    if (!isDemoSource(options.sources.front()))
        return std::nullopt;
    const std::string name = options.sources.front().substr(kDemoPrefix.size());
    std::optional<timeline::Timeline> history = surfaceDemoHistory(name);
    if (!history)
        return std::nullopt;
    DesignedFrame design;
    design.timeline = std::move(*history);
    design.displayName = name;
    design.frame = chosenFrame(options, design.timeline.frameCount() - 1, design.displayName);
    return design;
}

} // namespace

DesignedClassification designedClassification(const RenderOptions& options, const DesignedFrame& design)
{
    DesignedClassification chosen{options.classification, options.trim.rule};
    if (!options.classificationGiven && design.savedClassification)
        chosen.classification = *design.savedClassification;
    if (!options.ruleGiven && design.savedRule)
        chosen.rule = *design.savedRule;
    return chosen;
}

DesignedFrame loadDesignedFrame(const RenderOptions& options)
{
    if (!options.script.isEmpty())
        return replayScript(options);
    if (std::optional<DesignedFrame> demo = demoHistory(options))
        return std::move(*demo);
    return loadProjectFile(options);
}

} // namespace trimlab::app
