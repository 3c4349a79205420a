/* What a program did not ask for, and what it cannot trust: an ekb.toml in a folder above the
 * file is not read (one that silences the tour rules does not let a bad tour load; a FIFO or
 * a folder in its place does not stop a clean load), settings named by settings_path are; a
 * file name with control characters and 900 KB of them comes back escaped and short.
 *
 * Usage: ekb-capi-untrusted CLEAN_FILE */
#define _XOPEN_SOURCE 700 /* mkdtemp, mkfifo */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "ekb.h"

static int failures = 0;

static void expect(ekb_status got, ekb_status want, const char *what) {
    if (got != want) {
        ekb_str g = ekb_status_name((int32_t)got), w = ekb_status_name((int32_t)want);
        fprintf(stderr, "FAIL %s: %.*s, want %.*s\n", what, (int)g.len, g.ptr, (int)w.len, w.ptr);
        ++failures;
    }
}

static void write_file(const char *path, const char *text, size_t len) {
    FILE *out = fopen(path, "wb");
    if (!out || fwrite(text, 1, len, out) != len || fclose(out) != 0) {
        fprintf(stderr, "cannot write %s\n", path);
        exit(2);
    }
}

static char *read_file(const char *path, size_t *len) {
    FILE *in = fopen(path, "rb");
    if (!in) exit(2);
    fseek(in, 0, SEEK_END);
    *len = (size_t)ftell(in);
    fseek(in, 0, SEEK_SET);
    char *text = malloc(*len + 64);
    if (fread(text, 1, *len, in) != *len) exit(2);
    fclose(in);
    return text;
}

/* Opens `path` and frees the handle; its status. */
static ekb_status open_status(const char *path, const ekb_options *options) {
    ekb_handle kb = 0;
    ekb_status status = ekb_open_path(path, strlen(path), options, &kb);
    ekb_free(kb);
    return status;
}

/* No byte of `text` is a control character, and it is at most `most` bytes. */
static void expect_safe(ekb_str text, size_t most, const char *what) {
    for (size_t i = 0; i < text.len; ++i)
        if ((unsigned char)text.ptr[i] < 0x20 || text.ptr[i] == 0x7f) {
            fprintf(stderr, "FAIL %s: a raw control byte 0x%02x at %zu\n", what, (unsigned char)text.ptr[i], i);
            ++failures;
            return;
        }
    if (text.len > most) {
        fprintf(stderr, "FAIL %s: %zu bytes, more than %zu\n", what, text.len, most);
        ++failures;
    }
}

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: ekb-capi-untrusted CLEAN_FILE\n");
        return 2;
    }
    char root[] = "/tmp/ekb-capi-untrusted-XXXXXX";
    if (!mkdtemp(root)) return 2;
    char sub[4096], kb[4096], toml[4096], bad[4096], named[4096];
    snprintf(sub, sizeof sub, "%s/lab", root);
    mkdir(sub, 0700);
    snprintf(toml, sizeof toml, "%s/ekb.toml", root);
    snprintf(named, sizeof named, "%s/named.toml", root);

    /* A clean file with a stop at a location that does not exist: refused, even under an
       ekb.toml that silences the tour rules; obeyed only when named. */
    size_t len = 0;
    char *clean = read_file(argv[1], &len);
    snprintf(bad, sizeof bad, "%s/bad-tour.dat", sub);
    const char *stop = "tourSpecification 2 1 9\n";
    char *tour = strstr(clean, "tourSpecification");
    if (!tour) return 2;
    size_t head = (size_t)(tour - clean);
    char *badText = malloc(head + strlen(stop) + 1);
    memcpy(badText, clean, head);
    strcpy(badText + head, stop);
    write_file(bad, badText, strlen(badText));
    const char *silencing = "[check]\nignore = [\"tour\"]\n";
    write_file(toml, silencing, strlen(silencing));
    write_file(named, silencing, strlen(silencing));
    expect(open_status(bad, NULL), EKB_REFUSED, "a bad tour under an ekb.toml that ignores the tour rules");
    ekb_options options;
    memset(&options, 0, sizeof options);
    options.settings_path.ptr = named;
    options.settings_path.len = strlen(named);
    expect(open_status(bad, &options), EKB_OK, "the same settings, named by settings_path");
    options.isolated = true;
    expect(open_status(bad, &options), EKB_REFUSED, "settings_path with isolated");

    /* A FIFO or a folder where ekb.toml would be: a clean file loads, at once. */
    snprintf(kb, sizeof kb, "%s/clean.dat", sub);
    write_file(kb, clean, len);
    unlink(toml);
    if (mkfifo(toml, 0600) != 0) return 2;
    expect(open_status(kb, NULL), EKB_OK, "a clean file under a FIFO ekb.toml");
    unlink(toml);
    mkdir(toml, 0700);
    expect(open_status(kb, NULL), EKB_OK, "a clean file under a folder ekb.toml");
    rmdir(toml);
    memset(&options, 0, sizeof options);
    options.settings_path.ptr = sub;
    options.settings_path.len = strlen(sub);
    expect(open_status(kb, &options), EKB_UNREADABLE, "settings_path naming a folder");

    /* A file name with ESC ] 0 ; BEL and 900 KB: the reason comes back escaped and short. */
    size_t longest = 900 * 1024;
    char *hostile = malloc(longest + 64);
    strcpy(hostile, "/nonexistent/\x1b]0;pwned\x07");
    memset(hostile + strlen(hostile), 'a', longest);
    hostile[longest] = '\0';
    ekb_handle missing = 0;
    expect(ekb_open_path(hostile, strlen(hostile), NULL, &missing), EKB_UNREADABLE, "a hostile file name");
    ekb_str message;
    expect(ekb_error_message(missing, &message), EKB_OK, "why it is unreadable");
    expect_safe(message, 2000, "the reason of a hostile file name");
    ekb_free(missing);
    /* The same name for a buffer, refused: each finding's file name escaped and short. */
    hostile[2000] = '\0';
    ekb_handle refused = 0;
    expect(ekb_open_buffer(hostile, strlen(hostile), (const uint8_t *)badText, strlen(badText), NULL, &refused),
           EKB_REFUSED, "a bad tour in a buffer with a hostile name");
    size_t count = 0;
    ekb_finding_count(refused, &count);
    for (size_t i = 0; i < count; ++i) {
        ekb_finding finding;
        ekb_finding_at(refused, i, &finding);
        expect_safe(finding.file, 2000, "a finding's file name");
        expect_safe(finding.message, 2000, "a finding's message");
    }
    expect(ekb_error_message(refused, &message), EKB_OK, "why it is refused");
    expect_safe(message, 4000, "the refusal of a hostile name");
    ekb_free(refused);

    unlink(bad);
    unlink(kb);
    unlink(named);
    rmdir(sub);
    rmdir(root);
    free(hostile);
    free(badText);
    free(clean);
    printf("C ABI untrusted input: %d failures\n", failures);
    return failures == 0 ? 0 : 1;
}
