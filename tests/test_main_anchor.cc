// The test binary is the test files (camopt_test_objects, linked after the engine) and gtest_main;
// an executable needs one source of its own.
