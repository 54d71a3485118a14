#pragma once
// The last N values of a measurement (frame times), oldest first, for ImGui::PlotLines.

#include <cstddef>
#include <vector>

namespace raylab::viewer {

class History {
public:
    explicit History(std::size_t capacity) : values_(capacity, 0.0f) {}

    void push(float value) {
        values_[next_] = value;
        next_ = (next_ + 1) % values_.size();
        count_ = count_ < values_.size() ? count_ + 1 : count_;
    }
    // The ring as PlotLines takes it: data, size and the index of the oldest value.
    const float* data() const { return values_.data(); }
    int size() const { return static_cast<int>(values_.size()); }
    int offset() const { return static_cast<int>(next_); }
    std::size_t count() const { return count_; } // values pushed, at most the capacity
    float latest() const {
        return count_ == 0 ? 0.0f : values_[(next_ + values_.size() - 1) % values_.size()];
    }
    // The mean of the values pushed so far (at most capacity), 0 when none.
    float mean() const {
        float sum = 0.0f;
        for (std::size_t i = 0; i < count_; ++i) {
            sum += values_[(next_ + values_.size() - 1 - i) % values_.size()];
        }
        return count_ == 0 ? 0.0f : sum / static_cast<float>(count_);
    }
    // Same capacity, values and ring position.
    bool operator==(const History&) const = default;

private:
    std::vector<float> values_;
    std::size_t next_ = 0;
    std::size_t count_ = 0;
};

} // namespace raylab::viewer
