#pragma once
/// \file
/// The document the main window shows (document.h), and the one place that replaces it:
/// features keep a reference to this holder, not to a document, and follow replaced()
/// and the current document's signals, which it forwards so that nobody has to reconnect
/// when a file is opened. The window owns it; WindowContext::document() reaches it.

#include "ui/common/document.h"

#include <QObject>

#include <memory>

namespace trimlab::ui {

class CurrentDocument : public QObject {
    Q_OBJECT
public:
    explicit CurrentDocument(QObject* parent = nullptr);
    ~CurrentDocument() override;

    /// The document shown; nullptr before the first file is opened.
    [[nodiscard]] Document* get() const { return m_document.get(); }
    /// Shows `document` in place of the current one, which is destroyed after replaced()
    /// (its undo stack with it).
    void replace(std::unique_ptr<Document> document);

signals:
    /// Another document is shown (get() is it).
    void replaced();
    /// The current document's modifiedChanged(), titleChanged() and settingsChanged().
    void modifiedChanged(bool modified);
    void titleChanged();
    void settingsChanged();

private:
    std::unique_ptr<Document> m_document;
};

} // namespace trimlab::ui
