#include "TestData.h"

const char *sortieTestData() { return SORTIE_TEST_DATA; }
