#include <lacrima/FapTable.h>
