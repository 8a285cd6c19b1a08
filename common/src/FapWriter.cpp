#include <lacrima/FapWriter.h>
