#include "singularity.h"

const char *sq_origin_name(sq_origin o)
{
    switch (o) {
    case SQ_ORIGIN_CRITICAL: return "critical-point";
    case SQ_ORIGIN_IMPOSED: return "imposed";
    case SQ_ORIGIN_MIDPOINT: return "midpoint";
    case SQ_ORIGIN_SPLIT: return "split";
    }
    return "unknown";
}
