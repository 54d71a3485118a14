#include "panel_signature.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <imgui.h>

namespace raylab::viewer {

namespace {

// A word-at-a-time hash (multiply and fold, as in wyhash/murmur's finalisers): not
// cryptographic, but every input bit reaches every output bit.
class Hasher {
public:
    void addBytes(const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        std::size_t i = 0;
        for (; i + 8 <= size; i += 8) {
            std::uint64_t word = 0;
            std::memcpy(&word, bytes + i, 8);
            addWord(word);
        }
        if (i < size) {
            std::uint64_t word = 0;
            std::memcpy(&word, bytes + i, size - i);
            addWord(word ^ (static_cast<std::uint64_t>(size - i) << 56));
        }
        addWord(size); // lengths too, so that moving bytes between fields changes the hash
    }
    void addWord(std::uint64_t word) {
        state_ = (state_ ^ word) * 0x9E3779B97F4A7C15ull;
        state_ ^= state_ >> 32;
    }
    template <typename T> void addValue(const T& value) { addBytes(&value, sizeof value); }
    std::uint64_t result() const {
        std::uint64_t h = state_;
        h ^= h >> 33;
        h *= 0xFF51AFD7ED558CCDull;
        h ^= h >> 33;
        return h;
    }

private:
    std::uint64_t state_ = 0x243F6A8885A308D3ull;
};

std::uint64_t pointerBits(const void* p) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &p, sizeof p);
    return bits;
}

} // namespace

PixelRect unite(const PixelRect& a, const PixelRect& b) {
    if (a.empty()) {
        return b;
    }
    if (b.empty()) {
        return a;
    }
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

PanelSignature panelSignature(const ImDrawData& data) {
    Hasher hasher;
    const ImVec2 pos = data.DisplayPos, size = data.DisplaySize, scale = data.FramebufferScale;
    for (const float v : {pos.x, pos.y, size.x, size.y, scale.x, scale.y}) {
        hasher.addValue(v);
    }
    // The framebuffer the renderer draws into (it skips frames with a zero side).
    const int fbWidth = static_cast<int>(size.x * scale.x);
    const int fbHeight = static_cast<int>(size.y * scale.y);
    PixelRect bounds;
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList& list = *data.CmdLists[n];
        hasher.addWord(static_cast<std::uint64_t>(n));
        hasher.addBytes(list.VtxBuffer.Data,
                        static_cast<std::size_t>(list.VtxBuffer.Size) * sizeof(ImDrawVert));
        hasher.addBytes(list.IdxBuffer.Data,
                        static_cast<std::size_t>(list.IdxBuffer.Size) * sizeof(ImDrawIdx));
        for (const ImDrawCmd& cmd : list.CmdBuffer) {
            // Field by field: ImDrawCmd has padding, whose bytes are not defined.
            hasher.addValue(cmd.ClipRect);
            hasher.addWord(pointerBits(cmd.TextureId));
            hasher.addWord(cmd.VtxOffset);
            hasher.addWord(cmd.IdxOffset);
            hasher.addWord(cmd.ElemCount);
            hasher.addWord(cmd.UserCallback != nullptr ? 1u : 0u);
            hasher.addWord(pointerBits(cmd.UserCallbackData));
            if (cmd.UserCallback != nullptr) {
                // A callback may draw anywhere: the whole framebuffer.
                bounds = unite(bounds, PixelRect{0, 0, fbWidth, fbHeight});
                continue;
            }
            // The triangles' bounding box within the clip rectangle (a window's background is
            // clipped to the whole display, so clip rectangles alone are loose), mapped as the
            // renderer maps them, rounded outwards and clamped to the framebuffer.
            float minX = cmd.ClipRect.z, minY = cmd.ClipRect.w;
            float maxX = cmd.ClipRect.x, maxY = cmd.ClipRect.y;
            const ImDrawIdx* indices = list.IdxBuffer.Data + cmd.IdxOffset;
            const ImDrawVert* vertices = list.VtxBuffer.Data + cmd.VtxOffset;
            for (unsigned i = 0; i < cmd.ElemCount; ++i) {
                const ImVec2 p = vertices[indices[i]].pos;
                minX = std::min(minX, p.x);
                minY = std::min(minY, p.y);
                maxX = std::max(maxX, p.x);
                maxY = std::max(maxY, p.y);
            }
            minX = std::max(minX, cmd.ClipRect.x);
            minY = std::max(minY, cmd.ClipRect.y);
            maxX = std::min(maxX, cmd.ClipRect.z);
            maxY = std::min(maxY, cmd.ClipRect.w);
            const PixelRect clip{
                std::max(0, static_cast<int>(std::floor((minX - pos.x) * scale.x))),
                std::max(0, static_cast<int>(std::floor((minY - pos.y) * scale.y))),
                std::min(fbWidth, static_cast<int>(std::ceil((maxX - pos.x) * scale.x))),
                std::min(fbHeight, static_cast<int>(std::ceil((maxY - pos.y) * scale.y)))};
            bounds = unite(bounds, clip);
        }
    }
    return {hasher.result(), bounds};
}

} // namespace raylab::viewer
