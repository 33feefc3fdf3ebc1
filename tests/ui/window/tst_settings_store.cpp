// What the GUI persists, without a window: render choices (with fallbacks for missing
// or broken values) and the recent-files list (order, limit, duplicates, demos).
#include "ui/common/last_directory.h"
#include "ui/window/recent_files.h"
#include "ui/render_panel/render_settings_store.h"

#include "render/mfr/kplus_buffer.h"
#include "render/mfr/fragment_method.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

using namespace trimlab;
using namespace trimlab::ui;

class TestSettingsStore : public QObject {
    Q_OBJECT
private slots:
    void init();
    void missingSettingsGiveFirstStartChoices();
    void renderChoicesRoundTrip();
    void brokenValuesFallBackFieldByField();
    void recentFilesKeepTheNewestTen();
    void saveDialogsStartInAWritableFolder();

private:
    std::unique_ptr<QTemporaryDir> m_dir;
    [[nodiscard]] QString iniPath() const { return m_dir->filePath(QStringLiteral("settings.ini")); }
};

void TestSettingsStore::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
}

void TestSettingsStore::missingSettingsGiveFirstStartChoices()
{
    const QSettings settings(iniPath(), QSettings::IniFormat);
    const RenderChoices choices = loadRenderChoices(settings);
    QVERIFY(choices.trim.trimEnabled);
    QCOMPARE(choices.trim.rule, StaticRule::AlternatingBorder);
    QVERIFY(!choices.trim.clip.enabled); // prepared, off: a new user sees the whole scene
    QCOMPARE(choices.trim.clip.normal, glm::dvec3(0.0, 0.0, -1.0));
    QCOMPARE(choices.trim.clip.offset, 0.0);
    QCOMPARE(choices.k, 16);
}

void TestSettingsStore::renderChoicesRoundTrip()
{
    RenderChoices saved;
    saved.trim.trimEnabled = false;
    saved.trim.rule = StaticRule::Parity;
    saved.trim.clip = ClipPlane{true, {0.25, -0.5, 1.0 / 3.0}, -0.125};
    saved.k = render::MethodParameters::kMaxK;
    {
        QSettings settings(iniPath(), QSettings::IniFormat);
        saveRenderChoices(settings, saved);
    }
    const QSettings settings(iniPath(), QSettings::IniFormat);
    const RenderChoices loaded = loadRenderChoices(settings);
    QCOMPARE(loaded.trim.trimEnabled, false);
    QCOMPARE(loaded.trim.rule, StaticRule::Parity);
    QCOMPARE(loaded.trim.clip.enabled, true);
    QCOMPARE(loaded.trim.clip.normal, saved.trim.clip.normal); // exact: doubles survive the INI file
    QCOMPARE(loaded.trim.clip.offset, -0.125);
    QCOMPARE(loaded.k, render::MethodParameters::kMaxK);
}

void TestSettingsStore::brokenValuesFallBackFieldByField()
{
    {
        QSettings settings(iniPath(), QSettings::IniFormat);
        settings.setValue(QStringLiteral("render/rule"), QStringLiteral("no-such-rule"));
        settings.setValue(QStringLiteral("render/k"), 0);
        settings.setValue(QStringLiteral("render/clipNormalX"), 0.0);
        settings.setValue(QStringLiteral("render/clipNormalY"), 0.0);
        settings.setValue(QStringLiteral("render/clipNormalZ"), 0.0);
        settings.setValue(QStringLiteral("render/clipOffset"), QStringLiteral("nan"));
        settings.setValue(QStringLiteral("render/trimEnabled"), false);
    }
    const QSettings settings(iniPath(), QSettings::IniFormat);
    const RenderChoices loaded = loadRenderChoices(settings);
    const RenderChoices fallback = firstStartRenderChoices();
    QCOMPARE(loaded.trim.rule, fallback.trim.rule);
    QCOMPARE(loaded.k, fallback.k);
    QCOMPARE(loaded.trim.clip.normal, fallback.trim.clip.normal);
    QCOMPARE(loaded.trim.clip.offset, fallback.trim.clip.offset);
    QCOMPARE(loaded.trim.trimEnabled, false); // the valid field is kept
}

void TestSettingsStore::recentFilesKeepTheNewestTen()
{
    RecentFiles recent;
    for (int i = 0; i < 12; ++i)
        recent.add(m_dir->filePath(QStringLiteral("mesh%1.obj").arg(i)));
    recent.add(QStringLiteral("demo:sphere"));
    recent.add(QString());
    QCOMPARE(recent.paths().size(), RecentFiles::kMaxEntries);
    QCOMPARE(recent.paths().front(), m_dir->filePath(QStringLiteral("mesh11.obj")));
    QCOMPARE(recent.paths().back(), m_dir->filePath(QStringLiteral("mesh2.obj")));
    // Re-adding moves to the front; a non-normalised spelling is the same file.
    recent.add(m_dir->path() + QStringLiteral("/./mesh5.obj"));
    QCOMPARE(recent.paths().front(), m_dir->filePath(QStringLiteral("mesh5.obj")));
    QCOMPARE(recent.paths().size(), RecentFiles::kMaxEntries);
    QCOMPARE(recent.paths().count(m_dir->filePath(QStringLiteral("mesh5.obj"))), 1);
    recent.remove(m_dir->filePath(QStringLiteral("mesh11.obj")));
    QCOMPARE(recent.paths().size(), RecentFiles::kMaxEntries - 1);
    {
        QSettings settings(iniPath(), QSettings::IniFormat);
        recent.save(settings);
    }
    RecentFiles restored;
    const QSettings settings(iniPath(), QSettings::IniFormat);
    restored.load(settings);
    QCOMPARE(restored.paths(), recent.paths());
}

// A file opened from a read-only folder (shared data, a mounted archive) must not make
// Export Image start there: save dialogs fall back to a writable folder.
void TestSettingsStore::saveDialogsStartInAWritableFolder()
{
    QSettings settings(iniPath(), QSettings::IniFormat);
    const QString writable = m_dir->filePath(QStringLiteral("writable"));
    const QString readOnly = m_dir->filePath(QStringLiteral("read-only"));
    QVERIFY(QDir().mkpath(writable) && QDir().mkpath(readOnly));
    const auto mount = [&](const QString& folder) { return folder != readOnly; }; // read-only as a mount is
    saveLastDirectory(settings, writable);
    QCOMPARE(loadSaveDirectory(settings, mount), writable);
    saveLastDirectory(settings, readOnly);
    QCOMPARE(loadLastDirectory(settings), readOnly); // opening still starts where the user was
    const QString start = loadSaveDirectory(settings, mount);
    QVERIFY(start != readOnly);
    QVERIFY(QFileInfo(start).isDir());
}

QTEST_GUILESS_MAIN(TestSettingsStore)
#include "tst_settings_store.moc"
