/* SPDX-License-Identifier: MIT */
/*
 * replay.c: runs a fuzz target over files without libFuzzer (gcc, with
 * address and undefined sanitizers: make fuzz-replay, part of make test):
 * every file named on the command line, and every file of every directory
 * named, is one input. The committed corpus (host_tests/fuzz/corpus/<target>:
 * seeds and every input that once crashed) is so a regression test.
 */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static long run_file(const char *path)
{
    FILE *fp = fopen(path, "rb");
    uint8_t *buf;
    long len;
    if (fp == NULL || fseek(fp, 0, SEEK_END) != 0 || (len = ftell(fp)) < 0 || fseek(fp, 0, SEEK_SET) != 0) {
        fprintf(stderr, "replay: cannot read %s\n", path);
        exit(2);
    }
    buf = malloc(len > 0 ? (size_t)len : 1);
    if (buf == NULL || fread(buf, 1, (size_t)len, fp) != (size_t)len) {
        fprintf(stderr, "replay: cannot read %s\n", path);
        exit(2);
    }
    fclose(fp);
    LLVMFuzzerTestOneInput(buf, (size_t)len);
    free(buf);
    return 1;
}

int main(int argc, char **argv)
{
    long n = 0;
    int i;
    for (i = 1; i < argc; i++) {
        struct stat sb;
        if (stat(argv[i], &sb) == 0 && S_ISDIR(sb.st_mode)) {
            DIR *dir = opendir(argv[i]);
            struct dirent *de;
            while (dir != NULL && (de = readdir(dir)) != NULL) {
                char path[4096];
                if (de->d_name[0] == '.') {
                    continue;
                }
                snprintf(path, sizeof path, "%s/%s", argv[i], de->d_name);
                n += run_file(path);
            }
            if (dir != NULL) {
                closedir(dir);
            }
        } else {
            n += run_file(argv[i]);
        }
    }
    printf("replayed %ld inputs\n", n);
    return n > 0 ? 0 : 1;
}
