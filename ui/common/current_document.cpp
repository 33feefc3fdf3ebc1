#include "ui/common/current_document.h"

namespace trimlab::ui {

CurrentDocument::CurrentDocument(QObject* parent) : QObject(parent)
{
}

CurrentDocument::~CurrentDocument() = default;

void CurrentDocument::replace(std::unique_ptr<Document> document)
{
    std::unique_ptr<Document> previous = std::move(m_document);
    if (previous)
        disconnect(previous.get(), nullptr, this, nullptr);
    m_document = std::move(document);
    if (m_document) {
        connect(m_document.get(), &Document::modifiedChanged, this, &CurrentDocument::modifiedChanged);
        connect(m_document.get(), &Document::titleChanged, this, &CurrentDocument::titleChanged);
        connect(m_document.get(), &Document::settingsChanged, this, &CurrentDocument::settingsChanged);
    }
    emit replaced();
    emit modifiedChanged(m_document && m_document->isModified());
    emit titleChanged();
}

} // namespace trimlab::ui
