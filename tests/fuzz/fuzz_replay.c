/* Replays fuzz inputs through LLVMFuzzerTestOneInput without libFuzzer, so the kept corpus
 * (tests/fuzz/corpus) runs as a regression test with any C compiler.
 * Usage: fuzz_core_replay FILE_OR_DIRECTORY...   (exit 0 when every input passes)
 *        fuzz_core_replay --skip REASON           (prints REASON, exits 77: ctest's skip) */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

static int replay_file(const char* path)
{
  FILE* f = fopen(path, "rb");
  long length;
  uint8_t* data;
  size_t got;
  if (!f)
  {
    fprintf(stderr, "cannot open %s\n", path);
    return 1;
  }
  fseek(f, 0, SEEK_END);
  length = ftell(f);
  fseek(f, 0, SEEK_SET);
  data = (uint8_t*)malloc(length > 0 ? (size_t)length : 1);
  got = length > 0 ? fread(data, 1, (size_t)length, f) : 0;
  fclose(f);
  LLVMFuzzerTestOneInput(data, got); /* aborts on a contract violation */
  free(data);
  return 0;
}

int main(int argc, char** argv)
{
  int i;
  int count = 0;
  int errors = 0;
  if (argc >= 2 && strcmp(argv[1], "--skip") == 0)
  {
    printf("skipped: %s\n", argc >= 3 ? argv[2] : "");
    return 77;
  }
  for (i = 1; i < argc; ++i)
  {
    struct stat st;
    if (stat(argv[i], &st) != 0)
    {
      fprintf(stderr, "no such file or directory: %s\n", argv[i]);
      ++errors;
      continue;
    }
    if (S_ISDIR(st.st_mode))
    {
      DIR* dir = opendir(argv[i]);
      struct dirent* entry;
      while (dir && (entry = readdir(dir)) != NULL)
      {
        char path[4096];
        if (entry->d_name[0] == '.')
        {
          continue;
        }
        snprintf(path, sizeof(path), "%s/%s", argv[i], entry->d_name);
        errors += replay_file(path);
        ++count;
      }
      if (dir)
      {
        closedir(dir);
      }
    }
    else
    {
      errors += replay_file(argv[i]);
      ++count;
    }
  }
  printf("replayed %d inputs, %d unreadable\n", count, errors);
  return errors == 0 && count > 0 ? 0 : 1;
}
