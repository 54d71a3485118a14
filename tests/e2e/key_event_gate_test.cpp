// KeyEventGate: what Dear ImGui 1.86 needs to see every key of a fast typist, in order.

#include "key_event_gate.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace raylab::viewer {
namespace {

constexpr int kRelease = 0; // GLFW_RELEASE, GLFW_PRESS, GLFW_REPEAT
constexpr int kPress = 1;
constexpr int kRepeat = 2;
constexpr int kKeyA = 65; // GLFW_KEY_A
constexpr int kEnter = 257;
constexpr int kShift = 340; // GLFW_KEY_LEFT_SHIFT, GLFW_KEY_LEFT_CONTROL
constexpr int kCtrl = 341;

KeyboardEvent key(int code, int action) {
    KeyboardEvent event;
    event.key = code;
    event.action = action;
    return event;
}

KeyboardEvent character(unsigned codepoint) {
    KeyboardEvent event;
    event.kind = KeyboardEvent::Kind::Char;
    event.codepoint = codepoint;
    return event;
}

// A compact trace of delivered events: "+65" press, "-65" release, "r65" repeat, "'a" character.
std::string describe(const std::vector<KeyboardEvent>& events) {
    std::string out;
    for (const KeyboardEvent& e : events) {
        if (!out.empty()) {
            out.push_back(' ');
        }
        if (e.kind == KeyboardEvent::Kind::Char) {
            out.push_back('\'');
            out.push_back(static_cast<char>(e.codepoint));
        } else {
            out.push_back(e.action == kPress ? '+' : e.action == kRelease ? '-' : 'r');
            out.append(std::to_string(e.key));
        }
    }
    return out;
}

// Offers `events` in one frame; returns what was delivered at once.
std::string offerAll(KeyEventGate& gate, const std::vector<KeyboardEvent>& events) {
    std::vector<KeyboardEvent> now;
    for (const KeyboardEvent& e : events) {
        if (gate.offer(e)) {
            now.push_back(e);
        }
    }
    return describe(now);
}

TEST(ViewerKeyEventGate, PressAndReleaseInOneFrameReachTwoFrames) {
    KeyEventGate gate(kPress, kRelease, {kShift, kCtrl});
    EXPECT_EQ(offerAll(gate, {key(kEnter, kPress), key(kEnter, kRelease)}), "+257");
    EXPECT_EQ(gate.waiting(), 1u);
    EXPECT_EQ(describe(gate.startFrame()), "-257");
    EXPECT_EQ(gate.waiting(), 0u);
    EXPECT_EQ(describe(gate.startFrame()), "");
}

TEST(ViewerKeyEventGate, CtrlAThenTypingKeepsTheOrderImGuiNeeds) {
    KeyEventGate gate(kPress, kRelease, {kShift, kCtrl});
    // xdotool key ctrl+a, then type "x", all before the next frame.
    EXPECT_EQ(
        offerAll(gate, {key(kCtrl, kPress), key(kKeyA, kPress), key(kKeyA, kRelease),
                        key(kCtrl, kRelease), key(88, kPress), character('x'), key(88, kRelease)}),
        "+341 +65");
    // The frame that sees Ctrl+A down selects all; then the releases and the next press.
    EXPECT_EQ(describe(gate.startFrame()), "-65 -341 +88");
    // The character comes a frame after its key's press (ImGui reads characters first).
    EXPECT_EQ(describe(gate.startFrame()), "'x -88");
    EXPECT_EQ(gate.waiting(), 0u);
}

TEST(ViewerKeyEventGate, CharactersBeforeAnyPressPassAtOnce) {
    KeyEventGate gate(kPress, kRelease, {kShift, kCtrl});
    EXPECT_EQ(offerAll(gate, {character('a'), character('b'), key(kKeyA, kRelease)}), "'a 'b -65");
}

TEST(ViewerKeyEventGate, ModifiersHoldUntilThePressIsSeen) {
    KeyEventGate gate(kPress, kRelease, {kShift, kCtrl});
    // xdotool key ctrl+a releases Ctrl before A: the frame must still see Ctrl held with A.
    EXPECT_EQ(offerAll(gate, {key(kCtrl, kPress), key(kKeyA, kPress), key(kCtrl, kRelease),
                              key(kKeyA, kRelease)}),
              "+341 +65");
    EXPECT_EQ(describe(gate.startFrame()), "-341 -65");
    EXPECT_EQ(describe(gate.startFrame()), "");
    // Shift+a typed fast: the character waits for the frame after the press.
    EXPECT_EQ(offerAll(gate, {key(kShift, kPress), key(kKeyA, kPress), character('A'),
                              key(kKeyA, kRelease), key(kShift, kRelease)}),
              "+340 +65");
    EXPECT_EQ(describe(gate.startFrame()), "'A -65 -340");
}

TEST(ViewerKeyEventGate, RepeatsPassUnlessSomethingWaits) {
    KeyEventGate gate(kPress, kRelease, {kShift, kCtrl});
    EXPECT_EQ(offerAll(gate, {key(kKeyA, kPress), key(kKeyA, kRepeat), key(kKeyA, kRepeat)}),
              "+65 r65 r65");
    EXPECT_EQ(offerAll(gate, {key(kKeyA, kRelease), key(kKeyA, kPress), key(kKeyA, kRepeat)}), "");
    EXPECT_EQ(describe(gate.startFrame()), "-65");
    EXPECT_EQ(describe(gate.startFrame()), "+65 r65");
}

TEST(ViewerKeyEventGate, DifferentKeysShareAFrame) {
    KeyEventGate gate(kPress, kRelease, {kShift, kCtrl});
    EXPECT_EQ(offerAll(gate, {key(265, kPress), key(kKeyA, kPress), key(290, kPress)}),
              "+265 +65 +290");
}

} // namespace
} // namespace raylab::viewer
