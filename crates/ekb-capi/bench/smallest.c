/* The smallest program on ekb.h (BENCHMARKS.md, "The loader's weight"): opens the file
 * named on its command line and prints its tour, one id a line. */
#include <stdio.h>
#include <string.h>

#include "ekb.h"

int main(int argc, char **argv) {
    ekb_handle kb;
    const uint32_t *stops;
    size_t count;
    if (argc != 2 || ekb_open_path(argv[1], strlen(argv[1]), NULL, &kb) != EKB_OK) return 1;
    if (ekb_tour(kb, &stops, &count) != EKB_OK) return 1;
    for (size_t stop = 0; stop < count; ++stop) printf("%u\n", (unsigned)stops[stop]);
    ekb_free(kb);
    return 0;
}
