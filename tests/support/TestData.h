#pragma once

// The folder of the tests' own data (tests/data), absolute. It is compiled into one file only
// (TestData.cpp): a path in a compile definition of every test would make each test's object
// differ between checkouts, and no test would ever be a ccache hit in a second clone.
const char *sortieTestData();
