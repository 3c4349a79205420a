/* The C ABI's misuse cases: each gets its error code, never undefined behaviour. In C,
 * so that ekb.h is checked as a C header too.
 *
 * Usage: ekb-capi-misuse CLEAN_FILE REFUSED_FILE */
#include <stdio.h>
#include <string.h>

#include "ekb.h"

static int failures = 0;

static void expect(ekb_status got, ekb_status want, const char *what) {
    if (got != want) {
        ekb_str g = ekb_status_name((int32_t)got), w = ekb_status_name((int32_t)want);
        fprintf(stderr, "FAIL %s: %.*s, want %.*s\n", what, (int)g.len, g.ptr, (int)w.len, w.ptr);
        ++failures;
    }
}

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: ekb-capi-misuse CLEAN_FILE REFUSED_FILE\n");
        return 2;
    }
    const char *clean = argv[1], *refused_path = argv[2];
    ekb_handle kb = 0, refused = 0, missing = 0;
    ekb_location location;
    ekb_finding finding;
    ekb_str text;
    size_t count = 0;
    const uint32_t *stops = NULL;

    expect(ekb_open_path(clean, strlen(clean), NULL, &kb), EKB_OK, "open a clean file");

    /* A null handle, a handle never opened. */
    expect(ekb_location_count(0, &count), EKB_NULL_HANDLE, "null handle");
    expect(ekb_free(0), EKB_NULL_HANDLE, "free the null handle");
    expect(ekb_location_count(kb + 1000, &count), EKB_STALE_HANDLE, "a handle never opened");

    /* Unknown ids and indexes out of range. */
    expect(ekb_location_by_id(kb, 0, &location), EKB_UNKNOWN_ID, "id 0");
    expect(ekb_location_by_id(kb, 2147483647u, &location), EKB_UNKNOWN_ID, "an unknown id");
    expect(ekb_cultural_word(kb, 2147483647u, 0, &text), EKB_UNKNOWN_ID, "words of an unknown id");
    expect(ekb_location_count(kb, &count), EKB_OK, "count");
    expect(ekb_location_at(kb, count, &location), EKB_BAD_ARGUMENT, "index past the end");
    expect(ekb_location_at(kb, 0, &location), EKB_OK, "the first location");
    expect(ekb_cultural_word(kb, location.id, location.cultural_knowledge_count, &text), EKB_BAD_ARGUMENT,
           "word past the end");
    expect(ekb_finding_at(kb, (size_t)-1, &finding), EKB_BAD_ARGUMENT, "finding past the end");

    /* Null outputs and bad inputs. */
    expect(ekb_location_count(kb, NULL), EKB_BAD_ARGUMENT, "null count");
    expect(ekb_location_at(kb, 0, NULL), EKB_BAD_ARGUMENT, "null location");
    expect(ekb_tour(kb, NULL, &count), EKB_BAD_ARGUMENT, "null stops");
    expect(ekb_tour(kb, &stops, NULL), EKB_BAD_ARGUMENT, "null tour count");
    expect(ekb_error_message(kb, NULL), EKB_BAD_ARGUMENT, "null message");
    expect(ekb_open_path(clean, strlen(clean), NULL, NULL), EKB_BAD_ARGUMENT, "null handle output");
    expect(ekb_open_path(NULL, 5, NULL, &missing), EKB_BAD_ARGUMENT, "null path with a length");
    /* A path is a file name, in bytes: one that is not UTF-8 is looked for (and missing here). */
    expect(ekb_open_path("/nonexistent/\xff\xfe", 15, NULL, &missing), EKB_UNREADABLE, "a path that is not UTF-8");
    expect(ekb_free(missing), EKB_OK, "free the non-UTF-8 path's handle");
    expect(ekb_open_buffer("kb.dat", 6, NULL, 10, NULL, &missing), EKB_BAD_ARGUMENT, "null data with a length");
    {
        ekb_options options;
        memset(&options, 0, sizeof options);
        options.reader.ptr = "2099-01";
        options.reader.len = 7;
        expect(ekb_open_path(clean, strlen(clean), &options, &missing), EKB_BAD_ARGUMENT, "an unknown reader");
        options.reader.ptr = "d5.4.2";
        options.reader.len = 6;
        expect(ekb_open_path(clean, strlen(clean), &options, &missing), EKB_OK, "a known reader");
        expect(ekb_reader(missing, &text), EKB_OK, "the reader");
        if (text.len != 6 || memcmp(text.ptr, "d5.4.2", 6) != 0) {
            fprintf(stderr, "FAIL the reader is %.*s\n", (int)text.len, text.ptr);
            ++failures;
        }
        expect(ekb_free(missing), EKB_OK, "free");
    }
    {
        /* The drop-in's STRING_LENGTH: 0 is the document's 200, 2 ..= 1048576 a size, the
           rest a bad argument (a field of 1 byte holds no text; 2^62 bytes no program has). */
        ekb_options options;
        memset(&options, 0, sizeof options);
        options.fixed_size_limits = true;
        options.string_length = 1;
        expect(ekb_open_path(clean, strlen(clean), &options, &missing), EKB_BAD_ARGUMENT, "a STRING_LENGTH of 1");
        options.string_length = (size_t)1 << 62;
        expect(ekb_open_path(clean, strlen(clean), &options, &missing), EKB_BAD_ARGUMENT, "a STRING_LENGTH of 2^62");
        options.string_length = (size_t)-1;
        expect(ekb_open_path(clean, strlen(clean), &options, &missing), EKB_BAD_ARGUMENT, "a STRING_LENGTH of SIZE_MAX");
        options.string_length = 0;
        expect(ekb_open_path(clean, strlen(clean), &options, &missing), EKB_OK, "the document's STRING_LENGTH");
        expect(ekb_free(missing), EKB_OK, "free");
        options.string_length = 600;
        expect(ekb_open_path(clean, strlen(clean), &options, &missing), EKB_OK, "the 2026-04 STRING_LENGTH");
        expect(ekb_free(missing), EKB_OK, "free");
    }
    expect(ekb_open_buffer("empty.dat", 9, NULL, 0, NULL, &missing), EKB_REFUSED, "an empty buffer has no tour");
    expect(ekb_free(missing), EKB_OK, "free the empty buffer's handle");

    /* A file that cannot be read, one that is refused: no locations, a reason, findings. */
    expect(ekb_open_path("/nonexistent/kb.dat", 19, NULL, &missing), EKB_UNREADABLE, "a missing file");
    expect(ekb_location_count(missing, &count), EKB_NOT_LOADED, "locations of an unreadable file");
    expect(ekb_error_message(missing, &text), EKB_OK, "why it is unreadable");
    if (text.len == 0) {
        fprintf(stderr, "FAIL an unreadable file has no reason\n");
        ++failures;
    }
    expect(ekb_open_path(refused_path, strlen(refused_path), NULL, &refused), EKB_REFUSED, "a file with errors");
    expect(ekb_tour(refused, &stops, &count), EKB_NOT_LOADED, "the tour of a refused file");
    expect(ekb_location_by_id(refused, 1, &location), EKB_NOT_LOADED, "a location of a refused file");
    expect(ekb_finding_count(refused, &count), EKB_OK, "findings of a refused file");
    if (count == 0) {
        fprintf(stderr, "FAIL a refused file has no findings\n");
        ++failures;
    }

    /* Stale handles: freed once, every later use is an error code, the next handle is new. */
    expect(ekb_free(kb), EKB_OK, "free");
    expect(ekb_free(kb), EKB_STALE_HANDLE, "free twice");
    expect(ekb_location_count(kb, &count), EKB_STALE_HANDLE, "use after free");
    expect(ekb_tour(kb, &stops, &count), EKB_STALE_HANDLE, "tour after free");
    expect(ekb_finding_count(kb, &count), EKB_STALE_HANDLE, "findings after free");
    {
        ekb_handle again = 0;
        expect(ekb_open_path(clean, strlen(clean), NULL, &again), EKB_OK, "open again");
        if (again == kb) {
            fprintf(stderr, "FAIL a freed handle was reused\n");
            ++failures;
        }
        expect(ekb_free(again), EKB_OK, "free again");
    }
    expect(ekb_free(refused), EKB_OK, "free the refused");
    expect(ekb_free(missing), EKB_OK, "free the unreadable");

    text = ekb_status_name(12345);
    if (text.len != 18 || memcmp(text.ptr, "EKB_UNKNOWN_STATUS", 18) != 0) {
        fprintf(stderr, "FAIL the name of an unknown status\n");
        ++failures;
    }
    printf("C ABI misuse: %d failures\n", failures);
    return failures == 0 ? 0 : 1;
}
