/* Corpus replay: runs every file of the checked-in corpus directory
 * (TS_FUZZ_CORPUS) through the harness, so that `make test` repeats what
 * the fuzzers found without libFuzzer (gcc builds, the sanitizer build).
 * A failing check aborts; otherwise prints "N passed, 0 failed". */
#define _DEFAULT_SOURCE
#include "fuzz.h"

#include <dirent.h>

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : TS_FUZZ_CORPUS;
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "%s: cannot open the corpus %s\n", TS_FUZZ_NAME, dir);
        printf("%s: 0 passed, 1 failed\n", TS_FUZZ_NAME);
        return 1;
    }
    long files = 0, bad = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.')
            continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        FILE *fp = fopen(path, "rb");
        if (!fp) {
            bad++;
            continue;
        }
        uint8_t *buf = malloc(1 << 20);
        size_t n = buf ? fread(buf, 1, 1 << 20, fp) : 0;
        fclose(fp);
        if (!buf) {
            bad++;
            continue;
        }
        LLVMFuzzerTestOneInput(buf, n);
        free(buf);
        files++;
    }
    closedir(d);
    printf("%s: %ld passed, %ld failed\n", TS_FUZZ_NAME, files, bad + (files == 0));
    return bad || files == 0;
}
