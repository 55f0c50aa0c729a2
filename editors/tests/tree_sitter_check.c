// Checks the tree-sitter grammar of sled with the tree-sitter runtime library (Debian's
// libtree-sitter-dev) and the generated parser in editors/tree-sitter-sled/src, without the
// tree-sitter CLI:
//
//   tree_sitter_check corpus FILE...   each test of the corpus files (the CLI's `tree-sitter
//                                      test` format) parses to its expected tree
//   tree_sitter_check parse FILE...    each file parses without an ERROR or MISSING node
//   tree_sitter_check tree FILE        prints the file's tree (for writing corpus tests)
//   tree_sitter_check keywords FILE    prints each statement's keyword (`row` for a table row),
//                                      in reading order: tree_sitter_test.sh compares them with
//                                      the statements of `sled check --dump-ast`
//
// Prints one line per failure and a closing `N passed, N failed`; exits 1 on any failure.
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <tree_sitter/api.h>

const TSLanguage *tree_sitter_sled(void);

static char *read_file(const char *path, size_t *size) {
  FILE *file = fopen(path, "rb");
  if (!file) return NULL;
  fseek(file, 0, SEEK_END);
  const long length = ftell(file);
  fseek(file, 0, SEEK_SET);
  char *text = malloc((size_t)length + 1);
  *size = fread(text, 1, (size_t)length, file);
  text[*size] = '\0';
  fclose(file);
  return text;
}

// Collapses whitespace so trees compare by structure: "( a  b )" and "(a b)" are equal.
static char *normalize(const char *text) {
  char *out = malloc(strlen(text) + 1);
  size_t n = 0;
  bool space = false;
  for (const char *p = text; *p; ++p) {
    if (*p == ' ' || *p == '\n' || *p == '\t' || *p == '\r') {
      space = n > 0;
      continue;
    }
    if (space && *p != ')' && out[n - 1] != '(') out[n++] = ' ';
    space = false;
    out[n++] = *p;
  }
  out[n] = '\0';
  return out;
}

static TSTree *parse(TSParser *parser, const char *text, size_t size) {
  return ts_parser_parse_string(parser, NULL, text, (uint32_t)size);
}

// The first ERROR or MISSING node under `node`, depth first; false when there is none.
static bool find_error(TSNode node, TSPoint *where, const char **what) {
  if (ts_node_is_missing(node) || strcmp(ts_node_type(node), "ERROR") == 0) {
    *where = ts_node_start_point(node);
    *what = ts_node_is_missing(node) ? "MISSING" : "ERROR";
    return true;
  }
  if (!ts_node_has_error(node)) return false;
  const uint32_t count = ts_node_child_count(node);
  for (uint32_t i = 0; i < count; ++i) {
    if (find_error(ts_node_child(node, i), where, what)) return true;
  }
  return false;
}

// Prints the keyword of every statement under `node` (`row` for rows), in reading order.
static void print_keywords(TSNode node, const char *text) {
  const char *type = ts_node_type(node);
  if (strcmp(type, "row") == 0) {
    printf("row\n");
  } else if (strcmp(type, "statement") == 0) {
    const TSNode keyword = ts_node_child_by_field_name(node, "keyword", 7);
    const uint32_t begin = ts_node_start_byte(keyword);
    printf("%.*s\n", (int)(ts_node_end_byte(keyword) - begin), text + begin);
  }
  const uint32_t count = ts_node_named_child_count(node);
  for (uint32_t i = 0; i < count; ++i) print_keywords(ts_node_named_child(node, i), text);
}

static bool is_rule(const char *line, char c) {
  size_t n = 0;
  while (line[n] == c) ++n;
  return n >= 3 && (line[n] == '\n' || line[n] == '\r' || line[n] == '\0');
}

int main(int argc, char **argv) {
  if (argc < 3 || (strcmp(argv[1], "corpus") != 0 && strcmp(argv[1], "parse") != 0 &&
                    strcmp(argv[1], "tree") != 0 && strcmp(argv[1], "keywords") != 0)) {
    fprintf(stderr, "usage: tree_sitter_check corpus|parse|tree|keywords FILE...\n");
    return 2;
  }
  const bool corpus = strcmp(argv[1], "corpus") == 0;
  TSParser *parser = ts_parser_new();
  if (!ts_parser_set_language(parser, tree_sitter_sled())) {
    fprintf(stderr, "tree_sitter_check: the parser's ABI does not match the runtime's\n");
    return 2;
  }
  int passed = 0;
  int failed = 0;
  for (int i = 2; i < argc; ++i) {
    size_t size = 0;
    char *text = read_file(argv[i], &size);
    if (!text) {
      printf("FAILED: cannot read %s\n", argv[i]);
      ++failed;
      continue;
    }
    if (strcmp(argv[1], "keywords") == 0) {
      TSTree *tree = parse(parser, text, size);
      print_keywords(ts_tree_root_node(tree), text);
      ts_tree_delete(tree);
      free(text);
      ts_parser_delete(parser);
      return 0;
    }
    if (strcmp(argv[1], "tree") == 0) {
      TSTree *tree = parse(parser, text, size);
      char *printed = ts_node_string(ts_tree_root_node(tree));
      printf("%s\n", printed);
      free(printed);
      ts_tree_delete(tree);
      free(text);
      ts_parser_delete(parser);
      return 0;
    }
    if (!corpus) {
      TSTree *tree = parse(parser, text, size);
      TSPoint where;
      const char *what;
      if (find_error(ts_tree_root_node(tree), &where, &what)) {
        printf("FAILED: %s:%u:%u: %s node\n", argv[i], where.row + 1, where.column + 1, what);
        ++failed;
      } else {
        ++passed;
      }
      ts_tree_delete(tree);
      free(text);
      continue;
    }
    // Corpus: `===` title `===`, the input, a `---` line, the expected tree; repeated.
    char *cursor = text;
    while (*cursor) {
      char *line = cursor;
      char *next = strchr(line, '\n');
      if (!is_rule(line, '=')) {
        cursor = next ? next + 1 : line + strlen(line);
        continue;
      }
      char *title = next ? next + 1 : line + strlen(line);
      char *title_end = strchr(title, '\n');
      if (!title_end) break;
      char *after = strchr(title_end + 1, '\n');  // the closing `===` of the header
      if (!after) break;
      char *input = after + 1;
      char *dashes = input;
      while (*dashes && !is_rule(dashes, '-')) {
        char *line_end = strchr(dashes, '\n');
        dashes = line_end ? line_end + 1 : dashes + strlen(dashes);
      }
      if (!*dashes) break;
      char *expected = strchr(dashes, '\n');
      expected = expected ? expected + 1 : dashes + strlen(dashes);
      char *end = expected;
      while (*end && !is_rule(end, '=')) {
        char *line_end = strchr(end, '\n');
        end = line_end ? line_end + 1 : end + strlen(end);
      }
      const char saved_end = *end;
      *end = '\0';
      const size_t input_size = (size_t)(dashes - input);
      TSTree *tree = parse(parser, input, input_size);
      char *actual = ts_node_string(ts_tree_root_node(tree));
      char *want = normalize(expected);
      char *got = normalize(actual);
      *title_end = '\0';
      if (strcmp(want, got) == 0) {
        ++passed;
      } else {
        printf("FAILED: %s: %s\n  expected: %s\n  actual:   %s\n", argv[i], title, want, got);
        ++failed;
      }
      *title_end = '\n';
      free(want);
      free(got);
      free(actual);
      ts_tree_delete(tree);
      *end = saved_end;
      cursor = end;
    }
    free(text);
  }
  ts_parser_delete(parser);
  printf("tree-sitter: %d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
