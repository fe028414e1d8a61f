// SPDX-License-Identifier: LGPL-2.1-or-later
// main() of every test executable: register all plugins, then run GoogleTest.
#include "register_all.h"

#include <deal.II/base/exceptions.h>
#include <gtest/gtest.h>

int
main(int argc, char **argv)
{
  dealii::deal_II_exceptions::disable_abort_on_exception();
  dealii::deal_II_exceptions::suppress_stacktrace_in_exceptions();
  wearlink::register_all();
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
