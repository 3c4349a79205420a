/* ekb.h from C: the tour of the file named on the command line. */
#include <stdio.h>
#include <string.h>

#include "ekb.h"

int main(int argc, char **argv) {
    ekb_handle kb = 0;
    const uint32_t *stops = NULL;
    size_t count = 0, i;
    if (argc != 2) return 2;
    if (ekb_open_path(argv[1], strlen(argv[1]), NULL, &kb) != EKB_OK) {
        ekb_str message;
        ekb_error_message(kb, &message);
        printf("%.*s\n", (int)message.len, message.ptr);
        ekb_free(kb);
        return 1;
    }
    ekb_tour(kb, &stops, &count);
    for (i = 0; i < count; i++) {
        ekb_location location;
        ekb_location_by_id(kb, stops[i], &location);
        printf("%u %.*s\n", location.id, (int)location.description.len, location.description.ptr);
    }
    ekb_free(kb);
    return 0;
}
