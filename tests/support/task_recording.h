#pragma once
/// \file
/// TaskControls for tests of long operations (core/util/task_control.h): one that records
/// the progress stages an operation reports, and one that requests a stop at the first
/// report of a given stage, so a test can check the stages and their order and that a
/// stop in each stage throws OperationCancelled.

#include "core/util/task_control.h"

#include <stop_token>
#include <string>
#include <vector>

namespace trimlab::test {

/// The stages a call reported, each once, in the order they began. Keep the recorder
/// alive while the call runs (the control refers to it).
struct StageRecorder {
    std::vector<std::string> stages;

    [[nodiscard]] TaskControl control()
    {
        TaskControl control;
        control.progress = [this](const TaskProgress& p) {
            if (stages.empty() || stages.back() != p.stage)
                stages.emplace_back(p.stage);
        };
        return control;
    }
};

/// Requests a stop at the first report of `stage`; `source.stop_requested()` afterwards
/// says whether the stage was reached. Keep it alive while the call runs.
struct StopAtStage {
    std::string stage;
    std::stop_source source;

    [[nodiscard]] TaskControl control()
    {
        TaskControl control;
        control.stop = source.get_token();
        control.progress = [this](const TaskProgress& p) {
            if (p.stage == stage)
                source.request_stop();
        };
        return control;
    }
};

} // namespace trimlab::test
