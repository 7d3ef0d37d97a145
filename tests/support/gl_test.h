#pragma once
// A headless GL 4.5 context shared by every test in one binary, with KHR_debug output
// turned into test failures: GlTest checks after each test that no GL error was reported.
#include <gtest/gtest.h>

#include "platform/gl_context.h"

namespace bz::test {

// Created on first use; lives until the process exits.
platform::GlContext& shared_context();

class GlTest : public ::testing::Test {
  protected:
    void SetUp() override;
    void TearDown() override;
    platform::GlContext& context() { return shared_context(); }
};

}  // namespace bz::test
