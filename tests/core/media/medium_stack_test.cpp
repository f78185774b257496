// The stack of volumes a path is in: nesting is last in, first out; overlapping volumes
// left out of order remove their own entry; leaving a volume never entered, or entering
// beyond capacity, changes nothing.
#include "core/media/medium_stack.h"

#include <gtest/gtest.h>

namespace penumbra {
namespace {

TEST(MediumStack, NestedVolumes) {
    MediumStack s;
    EXPECT_EQ(s.current(), -1);
    s.enter(3);  // glass
    s.enter(5);  // liquid inside it
    EXPECT_EQ(s.current(), 5);
    EXPECT_EQ(s.enclosing(), 3);
    s.leave(5);
    EXPECT_EQ(s.current(), 3);
    s.leave(3);
    EXPECT_TRUE(s.empty());
}

TEST(MediumStack, OverlapsTakeTheLastEnteredAndLeaveInAnyOrder) {
    MediumStack s;
    s.enter(1);
    s.enter(2);
    s.leave(1);  // out of 1 while still in 2
    EXPECT_EQ(s.current(), 2);
    EXPECT_EQ(s.size(), 1);
    s.leave(2);
    EXPECT_TRUE(s.empty());
    // The same material entered twice (two overlapping meshes of one material).
    s.enter(4);
    s.enter(4);
    s.leave(4);
    EXPECT_EQ(s.current(), 4);
    s.leave(4);
    EXPECT_TRUE(s.empty());
}

TEST(MediumStack, LeavingWhatWasNotEnteredAndOverflowChangeNothing) {
    MediumStack s;
    s.leave(7);  // e.g. a camera inside a volume: its rays start outside
    EXPECT_TRUE(s.empty());
    s.enter(1);
    s.leave(7);
    EXPECT_EQ(s.current(), 1);
    for (int i = 0; i < MediumStack::kCapacity + 3; ++i) s.enter(10 + i);
    EXPECT_EQ(s.size(), MediumStack::kCapacity);
    EXPECT_EQ(s.current(), 10 + MediumStack::kCapacity - 2);
}

TEST(MediumStack, LeaveWhereDropsTheEntriesOfRuledOutInstancesOnly) {
    MediumStack s;
    s.enter(1, 5);
    s.enter(2);  // instance unknown: never dropped
    s.enter(3, 6);
    s.enter(1, 7);
    s.leave_where([](int instance) { return instance == 5 || instance == 7; });
    ASSERT_EQ(s.size(), 2);
    EXPECT_EQ(s.current(), 3);
    EXPECT_EQ(s.enclosing(), 2);
    s.leave_where([](int) { return true; });
    EXPECT_EQ(s.current(), 2);
    s.leave(3);  // already gone: nothing changes
    EXPECT_EQ(s.current(), 2);
}

}  // namespace
}  // namespace penumbra
