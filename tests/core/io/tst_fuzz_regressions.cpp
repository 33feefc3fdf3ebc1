// Reliability corpus (docs/reliability.md):
// - every file in tests/data/fuzz-regressions/<target>/ (inputs the fuzzers in fuzz/
//   found, plus hand-picked hostile inputs) goes through the same loader as its fuzz
//   target and must load or fail with that loader's typed error — never crash, hang or
//   throw anything else;
// - every broken project file (version 1 and 2), stroke script, animation, NURBS file,
//   skeleton file and subdivision cage in tests/data/broken/ (make_broken_documents.py,
//   the cages by hand) must fail through its public loader with the exact error of the
//   table below; NURBS files also through loadScene, the path of `trimlab info` and
//   `trimlab render`.
#include "test_paths.h"

#include "core/animation/animation_loader.h"
#include "core/animation/gltf_animation.h"
#include "core/animation/sequence_loader.h"
#include "core/io/pfm_image.h"
#include "core/mesh/gzip_input.h"
#include "core/mesh/mesh_io.h"
#include "core/catalog/scene_source.h"
#include "core/surface/cage_obj.h"
#include "core/surface/nurbs_json.h"
#include "core/surface/nurbs_surface.h"
#include "core/io/file_bytes.h"
#include "core/timeline/project_file.h"
#include "core/timeline/stroke_script.h"
#include "core/skeleton/skeleton_json.h"
#include "core/trim/clip_plane.h"
#include "core/view/camera.h"

#include <QtTest>

#include <cmath>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <typeinfo>
#include <utility>

using namespace trimlab;
using trimlab::test::testDataPath;

namespace {

std::string readAll(const std::filesystem::path& path)
{
    return io::readFileBytes(path, std::size_t(1) << 26);
}

// Throws std::logic_error (an untyped failure: the regression fails) when the surface
// evaluates to a non-finite point or normal on a 3×3 grid of its domain, ends included.
void requireFiniteNurbsSamples(const NurbsSurface& surface)
{
    const ParameterRange ru = parameterRangeU(surface);
    const ParameterRange rv = parameterRangeV(surface);
    for (int i = 0; i <= 2; ++i) {
        for (int j = 0; j <= 2; ++j) {
            const double u = ru.begin + ru.length() * i / 2.0;
            const double v = rv.begin + rv.length() * j / 2.0;
            const glm::dvec3 p = evaluateNurbsPoint(surface, u, v);
            const glm::dvec3 n = nurbsNormal(surface, u, v);
            for (int c = 0; c < 3; ++c) {
                if (!std::isfinite(p[c]) || !std::isfinite(n[c]))
                    throw std::logic_error("the surface evaluates to a non-finite point or normal");
            }
        }
    }
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
        {"gltf",
         [](const auto& p) {
             const std::string bytes = readAll(p);
             (void)loadMeshFromMemory(bytes, bytes.starts_with("glTF") ? "glb" : "gltf", p.string());
         }},
        {"gzip_mesh",
         [](const auto& p) {
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
        {"gltf_animation",
         [](const auto& p) {
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
        {"pfm", [](const auto& p) { (void)io::readPfm(p); }},
        {"skeleton_json", [](const auto& p) { (void)parseSkeletonJson(readAll(p), p.string()); }},
        {"nurbs_json",
         [](const auto& p) {
             // As fuzz_nurbs_json: a surface that loads evaluates to finite points and
             // normals on a 3×3 parameter grid, ends included.
             for (const NurbsSurface& surface : parseNurbsJson(readAll(p), p.string()))
                 requireFiniteNurbsSamples(surface);
         }},
        {"cage_obj", [](const auto& p) { (void)loadCageObj(p); }},
        {"cli_values",
         [](const auto& p) {
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
    if (target == "nurbs_json")
        return dynamic_cast<const NurbsFileError*>(&error) != nullptr;
    if (target == "cli_values")
        return false;
    return dynamic_cast<const MeshLoadError*>(&error) != nullptr;
}

// The loader a broken document of tests/data/broken/ goes to, told by its name.
enum class DocumentKind { Project, StrokeScript, Animation, Nurbs, Skeleton, Cage };

std::optional<DocumentKind> documentKind(const std::string& name)
{
    static constexpr std::pair<std::string_view, DocumentKind> kPrefixes[] = {
        {"script_", DocumentKind::StrokeScript}, {"anim_", DocumentKind::Animation}, {"nurbs_", DocumentKind::Nurbs},
        {"skeleton_", DocumentKind::Skeleton},   {"cage_", DocumentKind::Cage},
    };
    if (name.ends_with(".trimlab"))
        return DocumentKind::Project;
    for (const auto& [prefix, kind] : kPrefixes)
        if (name.starts_with(prefix))
            return kind;
    return std::nullopt; // a broken mesh: tst_mesh_io.cpp's table
}

void loadDocument(const std::filesystem::path& path, DocumentKind kind)
{
    switch (kind) {
    case DocumentKind::Project:
        (void)timeline::readProject(path);
        return;
    case DocumentKind::StrokeScript:
        (void)timeline::loadStrokeScript(path);
        return;
    case DocumentKind::Animation:
        (void)loadAnimation(path.string(), {}, {});
        return;
    case DocumentKind::Nurbs:
        (void)loadNurbsJson(path);
        return;
    case DocumentKind::Skeleton:
        (void)loadSkeletonJson(path);
        return;
    case DocumentKind::Cage:
        (void)loadCageObj(path);
        return;
    }
}

// Whether `error` is the typed error the loader of `kind` documents.
bool isDocumentError(const std::exception& error, DocumentKind kind)
{
    switch (kind) {
    case DocumentKind::Project:
        return dynamic_cast<const timeline::ProjectFileError*>(&error) != nullptr;
    case DocumentKind::StrokeScript:
        return dynamic_cast<const timeline::StrokeScriptError*>(&error) != nullptr;
    case DocumentKind::Nurbs:
        return dynamic_cast<const NurbsFileError*>(&error) != nullptr;
    case DocumentKind::Skeleton:
        return dynamic_cast<const SkeletonFileError*>(&error) != nullptr;
    case DocumentKind::Animation:
    case DocumentKind::Cage:
        return dynamic_cast<const MeshLoadError*>(&error) != nullptr;
    }
    return false;
}

// Loads a broken document the way the GUI and the batch verbs do; returns the message
// of the typed error, or a description of what happened instead.
std::string brokenDocumentError(const std::filesystem::path& path, DocumentKind kind)
{
    try {
        loadDocument(path, kind);
    } catch (const std::exception& error) {
        if (isDocumentError(error, kind))
            return error.what();
        return std::string("wrong type ") + typeid(error).name() + ": " + error.what();
    }
    return "loaded without an error";
}

// The message of loadScene's MeshLoadError (`trimlab info` / `render` on a NURBS file).
std::string sceneError(const std::filesystem::path& path)
{
    try {
        (void)loadScene(path.string());
    } catch (const MeshLoadError& error) {
        return error.what();
    } catch (const std::exception& error) {
        return std::string("wrong type ") + typeid(error).name() + ": " + error.what();
    }
    return "loaded without an error";
}

// Messages start with the file name as given; compare from the file name on.
QString withoutFolder(std::string message, const std::filesystem::path& path)
{
    const std::string prefix = path.parent_path().string() + "/";
    if (message.starts_with(prefix))
        message.erase(0, prefix.size());
    return QString::fromStdString(message);
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

// tests/data/broken/ project files, stroke scripts, animations, NURBS files, cages and
// skeleton files with the exact error each must produce (tests/data/README.md lists them
// with their contents).
const std::vector<std::pair<const char*, const char*>> kBrokenDocuments = {
    {"anim_bad_channel_node.gltf",
     "anim_bad_channel_node.gltf: animation 0 channel 0: the target node 9 does not exist"},
    {"anim_bad_interpolation.gltf",
     "anim_bad_interpolation.gltf: animation 0 sampler 0: unknown interpolation 'CUBIC'"},
    {"anim_decreasing_times.gltf", "anim_decreasing_times.gltf: animation 0 sampler 0: keyframe times must increase "
                                   "strictly (time 2 is not after time 1)"},
    {"anim_huge_keyframes.gltf", "anim_huge_keyframes.gltf: animation 0 sampler 0: accessor 3: 2000000000 elements of "
                                 "4 bytes from byte offset 0 do not fit in buffer view 3 (12 bytes)"},
    {"anim_joint_out_of_range.gltf",
     "anim_joint_out_of_range.gltf: mesh 0 primitive 0: vertex 0 names joint 5.000000, but the skin has 2 joints"},
    {"anim_missing_inverse_bind.gltf",
     "anim_missing_inverse_bind.gltf: skin 0: has 2 joints but 1 inverse bind matrices"},
    {"anim_nan_time.gltf", "anim_nan_time.gltf: animation 0 sampler 0: accessor 3: element 1 is not finite (nan)"},
    {"anim_no_animations.gltf", "anim_no_animations.gltf: the file has no animations"},
    {"anim_seq_empty_pose", "anim_seq_empty_pose/pose_1.obj: the file is empty (0 bytes)"},
    {"anim_seq_fewer_vertices", "anim_seq_fewer_vertices/pose_1.obj: has 9 vertices but the first pose has 10"},
    {"anim_seq_out_of_range",
     "anim_seq_out_of_range/pose_1.obj:20: face 9 references vertex 99, but the file has only 10 vertices"},
    {"anim_seq_truncated_pose",
     "anim_seq_truncated_pose/pose_1.obj:6: a vertex needs 3 coordinates (v x y z), but this line has 2"},
    {"anim_weights_count.gltf",
     "anim_weights_count.gltf: animation 0 sampler 0: has 3 keyframe times but 2 output numbers; expected 3"},
    {"cage_crease_not_edge.obj", "cage_crease_not_edge.obj:16: crease 0 (0-2) is not an edge of the cage; a crease "
                                 "must join two corners that follow each other in a face"},
    {"cage_empty.obj", "cage_empty.obj: the file is empty (0 bytes)"},
    {"cage_huge_tag.obj",
     "cage_huge_tag.obj:16: tag 'crease' declares 2000000000 integers and 1 numbers, but the line ends after 3"},
    {"cage_inconsistent_orientation.obj",
     "cage_inconsistent_orientation.obj:12: cage edge 4-5 runs the same way in faces 1 and 2 (inconsistent "
     "orientation); reverse one of them so neighbours agree"},
    {"cage_nan.obj", "cage_nan.obj:4: vertex 3 has a non-finite coordinate (nan); coordinates must be finite numbers"},
    {"cage_negative_index.obj", "cage_negative_index.obj:15: face references vertex -9 (counting back), but only 8 "
                                "vertices are defined before this line"},
    {"cage_nonmanifold.obj", "cage_nonmanifold.obj:17: cage edge 0-1 is used by 3 faces (non-manifold; first faces 0, "
                             "2, 6); each edge may border at most two faces"},
    {"cage_out_of_range.obj", "cage_out_of_range.obj:15: face 6 references vertex 9, but the file has only 8 vertices"},
    {"cage_repeated_corner.obj",
     "cage_repeated_corner.obj:15: cage face 5 repeats vertex 4; remove the repeated corner"},
    {"cage_truncated.obj", "cage_truncated.obj:9: a vertex needs 3 coordinates (v x y z), but this line has 2"},
    {"cage_two_corners.obj", "cage_two_corners.obj:15: the face has 2 vertices; a face needs at least 3"},
    {"nurbs_count_text.nurbs.json",
     "nurbs_count_text.nurbs.json: surfaces[0].countU: must be an integer in [2, 1000000], not a string"},
    {"nurbs_decreasing_knots.nurbs.json", "nurbs_decreasing_knots.nurbs.json: surfaces[0].knotsU[4]: knots must not "
                                          "decrease (0.25 after 0.5); sort the knot vector"},
    {"nurbs_degree_out_of_range.nurbs.json",
     "nurbs_degree_out_of_range.nurbs.json: surfaces[0].degreeU: must be an integer in [1, 7], not 9"},
    {"nurbs_empty.nurbs.json", "nurbs_empty.nurbs.json: invalid JSON at line 1, column 1: the document is empty"},
    {"nurbs_huge_count.nurbs.json", "nurbs_huge_count.nurbs.json: surfaces[0].countV: countU·countV = 10000000000 "
                                    "control points are more than the limit of 1000000; split the surface"},
    {"nurbs_nan.nurbs.json", "nurbs_nan.nurbs.json: invalid JSON at line 65, column 6: syntax error while parsing "
                             "value - invalid literal; last read: '1.0,<U+000A>     N'"},
    {"nurbs_newer_version.nurbs.json",
     "nurbs_newer_version.nurbs.json: version: version 2 is newer than this TrimLab (1); update TrimLab to open it"},
    {"nurbs_overflow.nurbs.json", "nurbs_overflow.nurbs.json: invalid JSON at line 113, column 5: the number 1e999 "
                                  "does not fit a double; use finite values"},
    {"nurbs_points_count.nurbs.json",
     "nurbs_points_count.nurbs.json: surfaces[0].points: 14 entries, but countU·countV = 15; give exactly that many"},
    {"nurbs_truncated.nurbs.json", "nurbs_truncated.nurbs.json: truncated JSON at line 56, column 7: syntax error "
                                   "while parsing array - unexpected end of input; expected ']'"},
    {"nurbs_zero_weight.nurbs.json", "nurbs_zero_weight.nurbs.json: surfaces[0].weights[7]: weights must be finite and "
                                     "> 0 (rational surfaces need positive weights)"},
    {"project_bad_base64.trimlab",
     "project_bad_base64.trimlab: frames[0].after.base64: damaged base64: character '#' at offset 2 is not base64"},
    {"project_bad_fovy.trimlab", "project_bad_fovy.trimlab: view.fovy_degrees: must be in (0, 180)"},
    {"project_before_mismatch.trimlab",
     "project_before_mismatch.trimlab: inconsistent history: frames[0]: the 'before' position (0.000000, 1.000000, "
     "0.250000) of vertex 2 differs from its current position (0.000000, 1.000000, 0.000000)"},
    {"project_count_mismatch.trimlab",
     "project_count_mismatch.trimlab: base_mesh.positions: holds 36 bytes, but count 12 needs 48"},
    {"project_crc_mismatch.trimlab", "project_crc_mismatch.trimlab: frames[0].after: CRC mismatch: stored 0x00003039, "
                                     "data 0xf072d0dd (the file is damaged)"},
    {"project_deep_nesting.trimlab", "project_deep_nesting.trimlab: not a TrimLab project: invalid JSON at line 1, "
                                     "column 113: arrays and objects are nested deeper than 64 levels"},
    {"project_empty.trimlab",
     "project_empty.trimlab: not a TrimLab project: invalid JSON at line 1, column 1: the document is empty"},
    {"project_huge_count.trimlab",
     "project_huge_count.trimlab: base_mesh.positions: holds 36 bytes, but count 2000000000 needs 8000000000"},
    {"project_missing_format.trimlab",
     "project_missing_format.trimlab: not a TrimLab project (\"format\" is not \"trimlab-project\")"},
    {"project_missing_sets.trimlab", "project_missing_sets.trimlab: missing field 'sets'"},
    {"project_nan_after.trimlab",
     "project_nan_after.trimlab: inconsistent history: frames[0]: the 'after' position of vertex 2 is not finite"},
    {"project_newer_version.trimlab",
     "project_newer_version.trimlab: version 7 is newer than this TrimLab (3); update TrimLab to open it"},
    {"project_not_json.trimlab", "project_not_json.trimlab: not a TrimLab project: invalid JSON at line 1, column 1: "
                                 "syntax error while parsing value - invalid literal; last read: 'h'"},
    {"project_radius_zero.trimlab", "project_radius_zero.trimlab: frames[0].stroke.radius: must be > 0"},
    {"project_sets_do_not_cover.trimlab",
     "project_sets_do_not_cover.trimlab: inconsistent history: the sets hold 2 frames but there are 1"},
    {"project_surface_base_mismatch.trimlab", "project_surface_base_mismatch.trimlab: inconsistent history: the "
                                              "history's base mesh has 9 vertices, the surface's tessellation 8"},
    {"project_surface_before_differs.trimlab",
     "project_surface_before_differs.trimlab: inconsistent history: frames[0]: control move 0: the 'before' position "
     "(1.000000, 1.000000, 0.250000) of control point 2 differs from its current position (1.000000, 1.000000, "
     "0.000000)"},
    {"project_surface_control_out_of_range.trimlab",
     "project_surface_control_out_of_range.trimlab: inconsistent history: frames[0]: control move 0: control point 8 "
     "is out of range (the surface has 8 control points)"},
    {"project_surface_huge_count.trimlab",
     "project_surface_huge_count.trimlab: surface.positions: holds 192 bytes, but count 2000000000 needs 16000000000"},
    {"project_surface_level_too_deep.trimlab",
     "project_surface_level_too_deep.trimlab: surface.level: must be an integer in [0, 5], not 6"},
    {"project_surface_nan_after.trimlab", "project_surface_nan_after.trimlab: inconsistent history: frames[0]: control "
                                          "move 0: the 'after' position of control point 2 is not finite"},
    {"project_triangle_out_of_range.trimlab", "project_triangle_out_of_range.trimlab: inconsistent history: base "
                                              "triangle 0 references vertex 7, but the mesh has only 3 vertices"},
    {"project_truncated.trimlab",
     "project_truncated.trimlab: truncated: the JSON document ends early (line 38, column 9, byte 652): syntax error "
     "while parsing array - unexpected end of input; expected ']'"},
    {"project_unknown_rule.trimlab", "project_unknown_rule.trimlab: sets[0].rule: unknown rule 'sideways' (known: "
                                     "additive, subtractive, intersection, confluent, homogeneous-confluent)"},
    {"project_vertex_out_of_range.trimlab", "project_vertex_out_of_range.trimlab: inconsistent history: frames[0]: "
                                            "vertex 3 is out of range (the mesh has 3 vertices)"},
    {"project_wrong_array_type.trimlab",
     "project_wrong_array_type.trimlab: base_mesh.positions.type: must be \"float32\", not \"uint32\""},
    {"project_wrong_format.trimlab",
     "project_wrong_format.trimlab: not a TrimLab project (\"format\" is not \"trimlab-project\")"},
    {"script_empty.json", "script_empty.json:1:1: invalid JSON: the document is empty"},
    {"script_missing_drag.json", "script_missing_drag.json: sets[0].strokes[0]: missing field 'drag'"},
    {"script_negative_radius.json", "script_negative_radius.json: sets[0].strokes[0].radius: must be > 0"},
    {"script_newer_version.json", "script_newer_version.json: version: version 2 is newer than this TrimLab (1)"},
    {"script_no_sets.json", "script_no_sets.json: sets: must hold at least one set"},
    {"script_short_anchor.json",
     "script_short_anchor.json: sets[0].strokes[0].anchor: must be an array of 3 numbers [x, y, z]"},
    {"script_step_out_of_range.json",
     "script_step_out_of_range.json: sets[0].strokes[0].smoothing.step: must be in (0, 1]"},
    {"script_strength_text.json",
     "script_strength_text.json: sets[0].strokes[0].strength: must be a number, not a string"},
    {"script_syntax_error.json", "script_syntax_error.json:1:36: invalid JSON: syntax error while parsing object key - "
                                 "unexpected ','; expected string literal"},
    {"script_too_many_iterations.json", "script_too_many_iterations.json: sets[0].strokes[0].smoothing.iterations: "
                                        "must be an integer in [0, 10000], not 10001"},
    {"script_unknown_field.json", "script_unknown_field.json: sets[0].strokes[0].strenght: unknown field (known "
                                  "fields: anchor, triangle, drag, radius, strength, profile, smoothing)"},
    {"script_unknown_profile.json",
     "script_unknown_profile.json: sets[0].strokes[0].profile: unknown profile 'soft' (known: smooth, linear, sharp)"},
    {"script_unknown_rule.json", "script_unknown_rule.json: sets[0].rule: unknown rule 'sideways' (known: additive, "
                                 "subtractive, intersection, confluent, homogeneous-confluent)"},
    {"script_wrong_format.json", "script_wrong_format.json: format: must be \"trimlab-stroke-script\", not "
                                 "\"trimlab-project\": not a TrimLab stroke script"},
    {"skeleton_edges_differ.json", "skeleton_edges_differ.json: edges[1]: is [2, 1] but bone 1 runs from joint 1 to 2"},
    {"skeleton_empty.json", "skeleton_empty.json: invalid JSON at line 1, column 1: the document is empty"},
    {"skeleton_negative_vertex_joint.json",
     "skeleton_negative_vertex_joint.json: vertex_joint[1]: must be an integer in [0, 2147483647], not -1"},
    {"skeleton_newer_version.json",
     "skeleton_newer_version.json: version: version 2 is newer than this TrimLab (1); update TrimLab to open it"},
    {"skeleton_parent_out_of_range.json",
     "skeleton_parent_out_of_range.json: parent[2]: parent 7 is not another joint of the 3 (only the root has none)"},
    {"skeleton_truncated.json", "skeleton_truncated.json: truncated JSON at line 27, column 2: syntax error while "
                                "parsing array - unexpected end of input; expected ']'"},
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
    const std::optional<DocumentKind> kind = documentKind(file.toStdString());
    QVERIFY2(kind, "no loader known for this name");
    QVERIFY2(std::filesystem::exists(path), path.c_str());
    QCOMPARE(withoutFolder(brokenDocumentError(path, *kind), path), expected);
    if (*kind == DocumentKind::Nurbs)
        QCOMPARE(withoutFolder(sceneError(path), path), expected);
}

void TestFuzzRegressions::everyBrokenDocumentIsListed()
{
    for (const auto& entry : std::filesystem::directory_iterator(testDataPath("broken"))) {
        const std::string name = entry.path().filename().string();
        if (!documentKind(name))
            continue;
        const bool listed = std::any_of(kBrokenDocuments.begin(), kBrokenDocuments.end(),
                                        [&](const auto& row) { return name == row.first; });
        QVERIFY2(listed, qPrintable(QString::fromStdString(name + " has no expected error in kBrokenDocuments")));
    }
}

QTEST_GUILESS_MAIN(TestFuzzRegressions)
#include "tst_fuzz_regressions.moc"
