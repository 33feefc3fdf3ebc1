#pragma once
/// \file
/// One layer of the shown content (shown_content.h): at most one content per owner, and
/// the dominant one shown — the owner that published last among those still publishing.
/// An owner that withdraws hands the layer back to the owner before it, whose content was
/// kept. The version is the stamp of the last change of what the layer shows; a change to
/// content that is not shown leaves it as it is, so nothing is uploaded for it.

#include "render/content_owner.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace trimlab::render {

template <class Content>
class OwnedLayer {
public:
    /// `content` becomes `owner`'s (replacing what it had) and the dominant content.
    void publish(ContentOwner owner, Content content, std::uint64_t stamp)
    {
        erase(owner);
        m_entries.push_back({owner, std::move(content)});
        m_version = stamp;
    }
    /// Drops `owner`'s content; true when it was shown (the layer changed).
    bool withdraw(ContentOwner owner, std::uint64_t stamp)
    {
        const bool wasShown = owner != ContentOwner::None && shownOwner() == owner;
        erase(owner);
        if (wasShown)
            m_version = stamp;
        return wasShown;
    }
    /// `owner`'s content, shown or not (nullptr: none), to change in place; call changed() after.
    [[nodiscard]] Content* of(ContentOwner owner)
    {
        const auto it = find(owner);
        return it == m_entries.end() ? nullptr : &it->content;
    }
    /// `owner`'s content changed in place; true when it is shown (the layer changed).
    bool changed(ContentOwner owner, std::uint64_t stamp)
    {
        if (owner == ContentOwner::None || shownOwner() != owner)
            return false;
        m_version = stamp;
        return true;
    }
    /// Everything goes (the meshes it belonged to were replaced).
    void clear(std::uint64_t stamp)
    {
        m_entries.clear();
        m_version = stamp;
    }

    /// The dominant content (nullptr: none).
    [[nodiscard]] const Content* shown() const { return m_entries.empty() ? nullptr : &m_entries.back().content; }
    [[nodiscard]] ContentOwner shownOwner() const
    {
        return m_entries.empty() ? ContentOwner::None : m_entries.back().owner;
    }
    [[nodiscard]] std::uint64_t version() const { return m_version; }

private:
    struct Entry {
        ContentOwner owner;
        Content content;
    };

    [[nodiscard]] typename std::vector<Entry>::iterator find(ContentOwner owner)
    {
        return std::find_if(m_entries.begin(), m_entries.end(), [owner](const Entry& e) { return e.owner == owner; });
    }
    void erase(ContentOwner owner)
    {
        const auto it = find(owner);
        if (it != m_entries.end())
            m_entries.erase(it);
    }

    std::vector<Entry> m_entries; ///< in the order of publication: the last is shown
    std::uint64_t m_version = 1;
};

} // namespace trimlab::render
