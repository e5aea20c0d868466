// The main of every test program: the product's process set-up (util/process_setup.h), then
// GoogleTest, so the tests run with the allocator set-up the program has.
#include <gtest/gtest.h>

#include "util/process_setup.h"

int main(int argc, char** argv) {
  luxgrid::set_up_process();
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
