// The build's large arrays (core/huge_pages.h, core/uninitialised_allocator.h): memory of their
// own on a 2 MiB boundary, advised transparent huge pages, usable over every byte asked for; new
// elements left unwritten.

#include "huge_pages.h"
#include "huge_pages_mode.h"
#include "uninitialised_allocator.h"

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <new>
#include <sstream>
#include <string>

namespace raylab {
namespace {

constexpr std::size_t kMiB = std::size_t{1} << 20;

bool onHugePageBoundary(const void* data) {
    return reinterpret_cast<std::uintptr_t>(data) % kHugePageBytes == 0;
}

// The value of `field` ("THPeligible:") in /proc/self/smaps for the mapping holding `address`;
// empty when there is none.
std::string smapsField(const void* address, const std::string& field) {
    std::ifstream smaps("/proc/self/smaps");
    const auto at = reinterpret_cast<std::uintptr_t>(address);
    bool inside = false;
    for (std::string line; std::getline(smaps, line);) {
        std::uintptr_t begin = 0, end = 0;
        char dash = 0;
        std::istringstream range(line);
        if (range >> std::hex >> begin >> dash >> end && dash == '-') {
            inside = begin <= at && at < end;
        } else if (inside && line.rfind(field, 0) == 0) {
            std::istringstream value(line.substr(field.size()));
            std::string word;
            value >> word;
            return word;
        }
    }
    return {};
}

TEST(HugePageArray, IsOnA2MiBBoundaryZeroedAndUsableOverEveryByte) {
    for (const std::size_t bytes : {2 * kMiB, 2 * kMiB + 1, 5 * kMiB + 123, 16 * kMiB}) {
        auto* data = static_cast<unsigned char*>(allocateHugePageArray(bytes));
        ASSERT_NE(data, nullptr);
        EXPECT_TRUE(onHugePageBoundary(data)) << bytes;
        std::size_t nonZero = 0;
        for (std::size_t i = 0; i < bytes; i += 4096) {
            nonZero += data[i] != 0;
        }
        EXPECT_EQ(data[bytes - 1], 0) << bytes;
        EXPECT_EQ(nonZero, 0u) << bytes;
        for (std::size_t i = 0; i < bytes; ++i) {
            data[i] = static_cast<unsigned char>(i * 7 + 3);
        }
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < bytes; ++i) {
            wrong += data[i] != static_cast<unsigned char>(i * 7 + 3);
        }
        EXPECT_EQ(wrong, 0u) << bytes;
        freeHugePageArray(data, bytes);
    }
}

TEST(HugePageArray, IsAdvisedHugePagesWhereTheKernelOffersThem) {
    if (!test::hugePagesOnRequest()) {
        GTEST_SKIP() << "transparent huge pages are off here (" << test::transparentHugePagesMode()
                     << ")";
    }
    const std::size_t bytes = 6 * kMiB;
    void* data = allocateHugePageArray(bytes);
    const std::string eligible = smapsField(data, "THPeligible:");
    freeHugePageArray(data, bytes);
    if (eligible.empty()) {
        GTEST_SKIP() << "this kernel's smaps does not say whether a mapping may take huge pages";
    }
    EXPECT_EQ(eligible, "1");
}

TEST(HugePageArray, ASizeTheSystemCannotMapThrowsBadAlloc) {
    EXPECT_THROW(allocateHugePageArray(std::numeric_limits<std::size_t>::max() - 100),
                 std::bad_alloc);
    EXPECT_THROW(allocateHugePageArray(std::size_t{1} << 60), std::bad_alloc);
}

TEST(UninitialisedVector, KeepsItsElementsAcrossTheHugePageThreshold) {
    UninitialisedVector<uint32_t> values;
    const std::size_t large = 3 * kHugePageBytes / sizeof(uint32_t) + 17;
    for (std::size_t i = 0; i < large; ++i) { // grows from the heap into huge pages
        values.push_back(static_cast<uint32_t>(i * 2654435761u));
    }
    EXPECT_TRUE(onHugePageBoundary(values.data()));
    UninitialisedVector<uint32_t> copy = values;
    EXPECT_TRUE(onHugePageBoundary(copy.data()));
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < large; ++i) {
        wrong += copy[i] != static_cast<uint32_t>(i * 2654435761u);
    }
    EXPECT_EQ(wrong, 0u);
    copy.resize(100);
    copy.shrink_to_fit(); // back to the heap
    ASSERT_EQ(copy.size(), 100u);
    EXPECT_EQ(copy[99], static_cast<uint32_t>(99 * 2654435761u));
    UninitialisedVector<uint32_t>().swap(values);
    EXPECT_EQ(values.capacity(), 0u);
    const UninitialisedVector<uint8_t> fromTheThreshold(kHugePageArrayBytes);
    EXPECT_TRUE(onHugePageBoundary(fromTheThreshold.data()));
}

// A plain struct with default member values, as the build's nodes are (BvhNode).
struct NodeLike {
    float lower = 0.0f;
    uint32_t index = 0;
    uint32_t count = 0;
};

// resize() writes nothing into the new elements, not even default member values: an array that
// is cleared and sized again, in the same memory, still holds what was written before, on the
// heap and in huge pages alike (the build writes each element once, on the thread that fills
// it).
TEST(UninitialisedVector, ResizeLeavesPlainStructsUnwrittenDefaultValuesIncluded) {
    for (const std::size_t count : {std::size_t{1000}, 3 * kHugePageBytes / sizeof(NodeLike)}) {
        UninitialisedVector<NodeLike> nodes(count);
        for (std::size_t i = 0; i < count; ++i) {
            nodes[i] = NodeLike{1.5f, static_cast<uint32_t>(i), 7};
        }
        const NodeLike* data = nodes.data();
        nodes.clear();
        nodes.resize(count);
        ASSERT_EQ(nodes.data(), data); // the same memory
        std::size_t written = 0;
        for (std::size_t i = 0; i < count; ++i) {
            written += nodes[i].index != i || nodes[i].count != 7 || nodes[i].lower != 1.5f;
        }
        EXPECT_EQ(written, 0u) << count << " elements";
        nodes.push_back(NodeLike{}); // a value given is written as given
        EXPECT_EQ(nodes.back().count, 0u);
    }
}

} // namespace
} // namespace raylab
