// Reliability corpus (docs/reliability.md):
// - every file in tests/data/fuzz-regressions/<target>/ (inputs the fuzzers in fuzz/
//   found, plus hand-picked hostile inputs) goes through the same loader as its fuzz
//   target and must load or fail with that loader's typed error — never crash, hang or
//   throw anything else;
// - every broken project file, stroke script and animation in tests/data/broken/
//   (make_broken_documents.py) must fail with the exact error of the table below.
#include "test_paths.h"

#include "animation/animation_loader.h"
#include "animation/gltf_animation.h"
#include "animation/sequence_loader.h"
#include "io/pfm_image.h"
#include "mesh/gzip_input.h"
#include "mesh/mesh_io.h"
#include "timeline/file_bytes.h"
#include "timeline/project_file.h"
#include "timeline/stroke_script.h"
#include "skeleton/skeleton_json.h"
#include "trim/clip_plane.h"
#include "view/camera.h"

#include <QtTest>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <typeinfo>

using namespace trimlab;
using trimlab::test::testDataPath;

namespace {

std::string readAll(const std::filesystem::path& path)
{
    return timeline::readFileBytes(path, std::size_t(1) << 26);
}

// The sequence fuzz input ("EXT\n" + poses joined by "~~~\n") written as pose files.
void loadSequenceInput(const std::string& input)
{
    std::string_view rest = input;
    std::string extension = "obj";
    const std::size_t newline = rest.find('\n');
    if (newline != std::string_view::npos) {
        const std::string_view first = rest.substr(0, newline);
        if (first == "obj" || first == "off" || first == "ply" || first == "stl") {
            extension = std::string(first);
            rest.remove_prefix(newline + 1);
        }
    }
    QTemporaryDir folder;
    std::vector<std::filesystem::path> files;
    for (int pose = 0; pose < 3; ++pose) {
        const std::size_t cut = pose < 2 ? rest.find("~~~\n") : std::string_view::npos;
        files.push_back(std::filesystem::path(folder.path().toStdString()) /
                        ("pose_" + std::to_string(pose) + "." + extension));
        QFile file(QString::fromStdString(files.back().string()));
        QVERIFY(file.open(QIODevice::WriteOnly));
        const std::string_view part = rest.substr(0, cut);
        file.write(part.data(), qint64(part.size()));
        file.close();
        if (cut == std::string_view::npos)
            break;
        rest.remove_prefix(cut + 4);
    }
    (void)loadMeshSequence(files, {}, 1);
}

// What each fuzz target does with one input (fuzz/fuzz_<target>.cpp); the typed error a
// target expects is caught by the caller.
const std::map<std::string, std::function<void(const std::filesystem::path&)>>& loaders()
{
    static const std::map<std::string, std::function<void(const std::filesystem::path&)>> table = {
        {"obj", [](const auto& p) { (void)loadMeshFromMemory(readAll(p), "obj", p.string()); }},
        {"off", [](const auto& p) { (void)loadMeshFromMemory(readAll(p), "off", p.string()); }},
        {"ply", [](const auto& p) { (void)loadMeshFromMemory(readAll(p), "ply", p.string()); }},
        {"stl", [](const auto& p) { (void)loadMeshFromMemory(readAll(p), "stl", p.string()); }},
        {"gltf", [](const auto& p) {
             const std::string bytes = readAll(p);
             (void)loadMeshFromMemory(bytes, bytes.starts_with("glTF") ? "glb" : "gltf", p.string());
         }},
        {"gzip_mesh", [](const auto& p) {
             const std::string bytes = readAll(p);
             try {
                 (void)gunzip(bytes, p.string(), 1 << 16);
             } catch (const MeshLoadError&) {
             }
             for (const char* extension : {"obj.gz", "off.gz", "ply.gz", "stl.gz"}) {
                 try {
                     (void)loadMeshFromMemory(bytes, extension, p.string());
                 } catch (const MeshLoadError&) {
                 }
             }
             (void)loadMeshFromMemory(bytes, "gltf.gz", p.string());
         }},
        {"gltf_animation", [](const auto& p) {
             const std::string bytes = readAll(p);
             GltfAnimationOptions options;
             try {
                 (void)readGltfAnimation(bytes, p.string(), {}, options);
             } catch (const MeshLoadError&) {
             }
             options.fps = 10.0;
             (void)readGltfAnimation(bytes, p.string(), {}, options);
         }},
        {"animation_sequence", [](const auto& p) { loadSequenceInput(readAll(p)); }},
        {"project", [](const auto& p) { (void)timeline::parseProject(readAll(p), p.string()); }},
        {"stroke_script", [](const auto& p) { (void)timeline::parseStrokeScript(readAll(p), p.string()); }},
        {"pfm", [](const auto& p) { (void)readPfm(p); }},
        {"skeleton_json", [](const auto& p) { (void)parseSkeletonJson(readAll(p), p.string()); }},
        {"cli_values", [](const auto& p) {
             const std::string text = readAll(p);
             std::string error;
             (void)parseCamera(text, &error);
             (void)parseClipPlane(text, &error);
         }},
    };
    return table;
}

bool isTypedError(const std::exception& error, const std::string& target)
{
    if (target == "project")
        return dynamic_cast<const timeline::ProjectFileError*>(&error) != nullptr;
    if (target == "stroke_script")
        return dynamic_cast<const timeline::StrokeScriptError*>(&error) != nullptr;
    if (target == "pfm")
        return dynamic_cast<const std::runtime_error*>(&error) != nullptr;
    if (target == "skeleton_json")
        return dynamic_cast<const SkeletonFileError*>(&error) != nullptr;
    if (target == "cli_values")
        return false;
    return dynamic_cast<const MeshLoadError*>(&error) != nullptr;
}

// Loads a broken document the way the GUI and the batch verbs do; returns the message
// of the typed error, or a description of what happened instead.
std::string brokenDocumentError(const std::filesystem::path& path)
{
    const std::string name = path.filename().string();
    try {
        if (name.ends_with(".trimlab"))
            (void)timeline::readProject(path);
        else if (name.starts_with("script_"))
            (void)timeline::loadStrokeScript(path);
        else
            (void)loadAnimation(path.string(), {}, {});
    } catch (const timeline::ProjectFileError& error) {
        return name.ends_with(".trimlab") ? error.what() : std::string("wrong type: ") + error.what();
    } catch (const timeline::StrokeScriptError& error) {
        return name.starts_with("script_") ? error.what() : std::string("wrong type: ") + error.what();
    } catch (const MeshLoadError& error) {
        return name.starts_with("anim_") ? error.what() : std::string("wrong type: ") + error.what();
    } catch (const std::exception& error) {
        return std::string("unexpected ") + typeid(error).name() + ": " + error.what();
    }
    return "loaded without an error";
}

} // namespace

class TestFuzzRegressions : public QObject {
    Q_OBJECT

private slots:
    void regressionFilesLoadOrFailTyped_data();
    void regressionFilesLoadOrFailTyped();
    void brokenDocumentsFailExactly_data();
    void brokenDocumentsFailExactly();
    void everyBrokenDocumentIsListed();
};

void TestFuzzRegressions::regressionFilesLoadOrFailTyped_data()
{
    QTest::addColumn<QString>("target");
    QTest::addColumn<QString>("file");
    const std::filesystem::path root = testDataPath("fuzz-regressions");
    QVERIFY2(std::filesystem::is_directory(root), root.c_str());
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
        if (entry.is_regular_file() && entry.path().filename() != "README.md")
            files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    QVERIFY(!files.empty());
    for (const auto& file : files) {
        const std::string target = file.parent_path().filename().string();
        const std::string row = target + "/" + file.filename().string();
        QTest::newRow(row.c_str()) << QString::fromStdString(target) << QString::fromStdString(file.string());
    }
}

void TestFuzzRegressions::regressionFilesLoadOrFailTyped()
{
    QFETCH(QString, target);
    QFETCH(QString, file);
    const auto loader = loaders().find(target.toStdString());
    QVERIFY2(loader != loaders().end(), qPrintable("no loader for folder " + target));
    try {
        loader->second(file.toStdString());
    } catch (const std::exception& error) {
        QVERIFY2(isTypedError(error, target.toStdString()),
                 qPrintable(QString("untyped %1: %2").arg(typeid(error).name(), error.what())));
    }
}

namespace {

// tests/data/broken/ project files, stroke scripts and animations with the exact error
// each must produce (tests/data/README.md lists them with their contents).
const std::vector<std::pair<const char*, const char*>> kBrokenDocuments = {
    {"anim_bad_channel_node.gltf",
     "anim_bad_channel_node.gltf: animation 0 channel 0: the target node 9 does not exist"},
    {"anim_bad_interpolation.gltf",
     "anim_bad_interpolation.gltf: animation 0 sampler 0: unknown interpolation 'CUBIC'"},
    {"anim_decreasing_times.gltf",
     "anim_decreasing_times.gltf: animation 0 sampler 0: keyframe times must increase strictly (time 2 is not after time 1)"},
    {"anim_huge_keyframes.gltf",
     "anim_huge_keyframes.gltf: animation 0 sampler 0: accessor 3: 2000000000 elements of 4 bytes from byte offset 0 do not fit in buffer view 3 (12 bytes)"},
    {"anim_joint_out_of_range.gltf",
     "anim_joint_out_of_range.gltf: mesh 0 primitive 0: vertex 0 names joint 5.000000, but the skin has 2 joints"},
    {"anim_missing_inverse_bind.gltf",
     "anim_missing_inverse_bind.gltf: skin 0: has 2 joints but 1 inverse bind matrices"},
    {"anim_nan_time.gltf",
     "anim_nan_time.gltf: animation 0 sampler 0: accessor 3: element 1 is not finite (nan)"},
    {"anim_no_animations.gltf",
     "anim_no_animations.gltf: the file has no animations"},
    {"anim_seq_empty_pose",
     "anim_seq_empty_pose/pose_1.obj: the file is empty (0 bytes)"},
    {"anim_seq_fewer_vertices",
     "anim_seq_fewer_vertices/pose_1.obj: has 9 vertices but the first pose has 10"},
    {"anim_seq_out_of_range",
     "anim_seq_out_of_range/pose_1.obj:20: face 9 references vertex 99, but the file has only 10 vertices"},
    {"anim_seq_truncated_pose",
     "anim_seq_truncated_pose/pose_1.obj:6: a vertex needs 3 coordinates (v x y z), but this line has 2"},
    {"anim_weights_count.gltf",
     "anim_weights_count.gltf: animation 0 sampler 0: has 3 keyframe times but 2 output numbers; expected 3"},
    {"project_bad_base64.trimlab",
     "project_bad_base64.trimlab: frames[0].after.base64: damaged base64: character '#' at offset 2 is not base64"},
    {"project_bad_fovy.trimlab",
     "project_bad_fovy.trimlab: view.fovy_degrees: must be in (0, 180)"},
    {"project_before_mismatch.trimlab",
     "project_before_mismatch.trimlab: inconsistent history: frames[0]: the 'before' position (0.000000, 1.000000, 0.250000) of vertex 2 differs from its current position (0.000000, 1.000000, 0.000000)"},
    {"project_count_mismatch.trimlab",
     "project_count_mismatch.trimlab: base_mesh.positions: holds 36 bytes, but count 12 needs 48"},
    {"project_crc_mismatch.trimlab",
     "project_crc_mismatch.trimlab: frames[0].after: CRC mismatch: stored 0x00003039, data 0xf072d0dd (the file is damaged)"},
    {"project_deep_nesting.trimlab",
     "project_deep_nesting.trimlab: not a TrimLab project: invalid JSON at line 1, column 113: arrays and objects are nested deeper than 64 levels"},
    {"project_empty.trimlab",
     "project_empty.trimlab: not a TrimLab project: invalid JSON at line 1, column 1: the document is empty"},
    {"project_huge_count.trimlab",
     "project_huge_count.trimlab: base_mesh.positions: holds 36 bytes, but count 2000000000 needs 8000000000"},
    {"project_missing_format.trimlab",
     "project_missing_format.trimlab: not a TrimLab project (\"format\" is not \"trimlab-project\")"},
    {"project_missing_sets.trimlab",
     "project_missing_sets.trimlab: missing field 'sets'"},
    {"project_nan_after.trimlab",
     "project_nan_after.trimlab: inconsistent history: frames[0]: the 'after' position of vertex 2 is not finite"},
    {"project_newer_version.trimlab",
     "project_newer_version.trimlab: version 7 is newer than this TrimLab (2); update TrimLab to open it"},
    {"project_not_json.trimlab",
     "project_not_json.trimlab: not a TrimLab project: invalid JSON at line 1, column 1: syntax error while parsing value - invalid literal; last read: 'h'"},
    {"project_radius_zero.trimlab",
     "project_radius_zero.trimlab: frames[0].stroke.radius: must be > 0"},
    {"project_sets_do_not_cover.trimlab",
     "project_sets_do_not_cover.trimlab: inconsistent history: the sets hold 2 frames but there are 1"},
    {"project_triangle_out_of_range.trimlab",
     "project_triangle_out_of_range.trimlab: inconsistent history: base triangle 0 references vertex 7, but the mesh has only 3 vertices"},
    {"project_truncated.trimlab",
     "project_truncated.trimlab: truncated: the JSON document ends early (line 38, column 9, byte 652): syntax error while parsing array - unexpected end of input; expected ']'"},
    {"project_unknown_rule.trimlab",
     "project_unknown_rule.trimlab: sets[0].rule: unknown rule 'sideways' (known: additive, subtractive, intersection, confluent, homogeneous-confluent)"},
    {"project_vertex_out_of_range.trimlab",
     "project_vertex_out_of_range.trimlab: inconsistent history: frames[0]: vertex 3 is out of range (the mesh has 3 vertices)"},
    {"project_wrong_array_type.trimlab",
     "project_wrong_array_type.trimlab: base_mesh.positions.type: must be \"float32\", not \"uint32\""},
    {"project_wrong_format.trimlab",
     "project_wrong_format.trimlab: not a TrimLab project (\"format\" is not \"trimlab-project\")"},
    {"script_empty.json",
     "script_empty.json:1:1: invalid JSON: the document is empty"},
    {"script_missing_drag.json",
     "script_missing_drag.json: sets[0].strokes[0]: missing field 'drag'"},
    {"script_negative_radius.json",
     "script_negative_radius.json: sets[0].strokes[0].radius: must be > 0"},
    {"script_newer_version.json",
     "script_newer_version.json: version: version 2 is newer than this TrimLab (1)"},
    {"script_no_sets.json",
     "script_no_sets.json: sets: must hold at least one set"},
    {"script_short_anchor.json",
     "script_short_anchor.json: sets[0].strokes[0].anchor: must be an array of 3 numbers [x, y, z]"},
    {"script_step_out_of_range.json",
     "script_step_out_of_range.json: sets[0].strokes[0].smoothing.step: must be in (0, 1]"},
    {"script_strength_text.json",
     "script_strength_text.json: sets[0].strokes[0].strength: must be a number, not a string"},
    {"script_syntax_error.json",
     "script_syntax_error.json:1:36: invalid JSON: syntax error while parsing object key - unexpected ','; expected string literal"},
    {"script_too_many_iterations.json",
     "script_too_many_iterations.json: sets[0].strokes[0].smoothing.iterations: must be an integer in [0, 10000], not 10001"},
    {"script_unknown_field.json",
     "script_unknown_field.json: sets[0].strokes[0].strenght: unknown field (known fields: anchor, triangle, drag, radius, strength, profile, smoothing)"},
    {"script_unknown_profile.json",
     "script_unknown_profile.json: sets[0].strokes[0].profile: unknown profile 'soft' (known: smooth, linear, sharp)"},
    {"script_unknown_rule.json",
     "script_unknown_rule.json: sets[0].rule: unknown rule 'sideways' (known: additive, subtractive, intersection, confluent, homogeneous-confluent)"},
    {"script_wrong_format.json",
     "script_wrong_format.json: format: must be \"trimlab-stroke-script\", not \"trimlab-project\": not a TrimLab stroke script"},
};

} // namespace

void TestFuzzRegressions::brokenDocumentsFailExactly_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("expected");
    for (const auto& [file, expected] : kBrokenDocuments)
        QTest::newRow(file) << QString(file) << QString(expected);
}

void TestFuzzRegressions::brokenDocumentsFailExactly()
{
    QFETCH(QString, file);
    QFETCH(QString, expected);
    const std::filesystem::path path = testDataPath("broken/" + file.toStdString());
    // Messages start with the file name as given; compare from the file name on.
    std::string message = brokenDocumentError(path);
    const std::string prefix = path.parent_path().string() + "/";
    if (message.starts_with(prefix))
        message.erase(0, prefix.size());
    QCOMPARE(QString::fromStdString(message), expected);
}

void TestFuzzRegressions::everyBrokenDocumentIsListed()
{
    for (const auto& entry : std::filesystem::directory_iterator(testDataPath("broken"))) {
        const std::string name = entry.path().filename().string();
        const bool document = name.ends_with(".trimlab") || name.starts_with("script_") || name.starts_with("anim_");
        if (!document)
            continue;
        const bool listed = std::any_of(kBrokenDocuments.begin(), kBrokenDocuments.end(),
                                        [&](const auto& row) { return name == row.first; });
        QVERIFY2(listed, qPrintable(QString::fromStdString(name + " has no expected error in kBrokenDocuments")));
    }
}

QTEST_GUILESS_MAIN(TestFuzzRegressions)
#include "tst_fuzz_regressions.moc"
