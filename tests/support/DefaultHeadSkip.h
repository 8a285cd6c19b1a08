#pragma once
// The missing-data skips live in MissingData.h. This name stays while
// tests/playback/TearQualityTest.cpp, rewritten on another branch, still includes it.
#include "MissingData.h"
