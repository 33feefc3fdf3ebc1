#pragma once
/// \file
/// A small open-addressing hash map from vertex ids to values: per-stroke bookkeeping
/// for the few thousand vertices near the anchor without allocating #V-sized arrays, at
/// a fraction of std::unordered_map's cost (one flat array, no node per entry).
/// Lookups only: it cannot be iterated, so its layout can never decide the order of a
/// floating-point sum (results stay deterministic).

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace trimlab::deform {

template <class Value>
class LocalVertexMap {
    static_assert(!std::is_same_v<Value, bool>, "std::vector<bool> has no addressable elements: use std::uint8_t");

public:
    /// Room for about `expected` entries before the first growth.
    explicit LocalVertexMap(std::size_t expected = 64)
    {
        std::size_t capacity = 16;
        while (capacity < 2 * expected)
            capacity *= 2;
        m_keys.assign(capacity, kEmpty);
        m_values.resize(capacity);
    }

    [[nodiscard]] std::size_t size() const { return m_size; }

    /// The value of `vertex`, or nullptr. The pointer is valid until the next insertion.
    [[nodiscard]] const Value* find(std::uint32_t vertex) const
    {
        const std::size_t slot = probe(vertex);
        return m_keys[slot] == vertex ? &m_values[slot] : nullptr;
    }
    [[nodiscard]] Value* find(std::uint32_t vertex)
    {
        const std::size_t slot = probe(vertex);
        return m_keys[slot] == vertex ? &m_values[slot] : nullptr;
    }

    /// The value of `vertex`, default-constructed when new. Valid until the next
    /// insertion. Throws std::invalid_argument for the reserved id 0xFFFFFFFF.
    Value& operator[](std::uint32_t vertex)
    {
        if (vertex == kEmpty)
            throw std::invalid_argument("LocalVertexMap: vertex id 0xFFFFFFFF is reserved");
        std::size_t slot = probe(vertex);
        if (m_keys[slot] == vertex)
            return m_values[slot];
        if (2 * (m_size + 1) > m_keys.size()) { // keep the load at most 1/2: short probes
            grow();
            slot = probe(vertex);
        }
        m_keys[slot] = vertex;
        m_values[slot] = Value{};
        ++m_size;
        return m_values[slot];
    }

private:
    static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;

    // Linear probing from a multiplicative (Fibonacci) hash: neighbouring vertex ids, which
    // a local region is full of, spread over the table.
    [[nodiscard]] std::size_t probe(std::uint32_t vertex) const
    {
        const std::size_t mask = m_keys.size() - 1;
        std::size_t slot = (std::uint64_t(vertex) * 0x9E3779B97F4A7C15ull >> 32) & mask;
        while (m_keys[slot] != vertex && m_keys[slot] != kEmpty)
            slot = (slot + 1) & mask;
        return slot;
    }

    void grow()
    {
        std::vector<std::uint32_t> keys(2 * m_keys.size(), kEmpty);
        std::vector<Value> values(keys.size());
        keys.swap(m_keys);
        values.swap(m_values);
        for (std::size_t i = 0; i < keys.size(); ++i) {
            if (keys[i] != kEmpty) {
                const std::size_t slot = probe(keys[i]);
                m_keys[slot] = keys[i];
                m_values[slot] = std::move(values[i]);
            }
        }
    }

    std::vector<std::uint32_t> m_keys;
    std::vector<Value> m_values;
    std::size_t m_size = 0;
};

} // namespace trimlab::deform
