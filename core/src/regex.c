/* Regex search with the master's semantics (JavaScript RegExp without flags, unanchored test()),
 * compiled per call into a small program on the stack and run as a Thompson automaton: time is
 * linear in the topic's length, memory fixed, no backtracking. Only match/no-match is computed,
 * so greedy and lazy quantifiers behave alike and groups need no captures.
 *
 * Text is matched byte by byte (UTF-8). A non-ASCII literal character is kept whole as one atom;
 * classes holding non-ASCII characters are refused (UBII_ERR_UNSUPPORTED), and '.' or a negated
 * class consumes a single byte of a multi-byte character, which cannot change whether a topic
 * matches unless a counted quantifier spans such characters. */
#include <string.h>

#include "regex_match.h"
#include "ubii/topic.h"

enum op {
    OP_CHAR,
    OP_ANY,
    OP_CLASS,
    OP_SPLIT,
    OP_JMP,
    OP_MATCH,
    OP_BOL,
    OP_EOL,
    OP_WORDB,
    OP_NWORDB
};

enum { MAX_REPEAT = 100 };

typedef struct inst {
    uint8_t op;
    uint8_t c; /* OP_CHAR: the byte; OP_CLASS: the class index */
    int16_t x; /* OP_JMP, OP_SPLIT: relative target */
    int16_t y; /* OP_SPLIT: second relative target */
} inst;

typedef struct program {
    inst code[UBII_REGEX_MAX_PROGRAM];
    int length;
    uint8_t classes[UBII_REGEX_MAX_CLASSES][32];
    int class_count;
} program;

typedef struct parser {
    const char *p;
    program *prog;
    ubii_status error;
} parser;

static bool fail(parser *ps, ubii_status error)
{
    if (ps->error == UBII_OK) {
        ps->error = error;
    }
    return false;
}

static bool emit(parser *ps, uint8_t op, uint8_t c, int x, int y)
{
    if (ps->prog->length >= UBII_REGEX_MAX_PROGRAM) {
        return fail(ps, UBII_ERR_TOO_LARGE);
    }
    inst *i = &ps->prog->code[ps->prog->length++];
    i->op = op;
    i->c = c;
    i->x = (int16_t)x;
    i->y = (int16_t)y;
    return true;
}

/* Inserts one instruction at `at`, shifting [at, length) up; relative jumps inside the shifted
 * block keep their meaning. */
static bool insert(parser *ps, int at, uint8_t op, int x, int y)
{
    program *prog = ps->prog;
    if (prog->length >= UBII_REGEX_MAX_PROGRAM) {
        return fail(ps, UBII_ERR_TOO_LARGE);
    }
    memmove(&prog->code[at + 1], &prog->code[at], (size_t)(prog->length - at) * sizeof(inst));
    prog->length++;
    prog->code[at].op = op;
    prog->code[at].c = 0;
    prog->code[at].x = (int16_t)x;
    prog->code[at].y = (int16_t)y;
    return true;
}

/* Appends a copy of code[from, from + size). */
static bool copy_block(parser *ps, int from, int size)
{
    program *prog = ps->prog;
    if (prog->length + size > UBII_REGEX_MAX_PROGRAM) {
        return fail(ps, UBII_ERR_TOO_LARGE);
    }
    memcpy(&prog->code[prog->length], &prog->code[from], (size_t)size * sizeof(inst));
    prog->length += size;
    return true;
}

/* ---- character classes --------------------------------------------------------------------------
 */

static void set_bit(uint8_t *set, unsigned c)
{
    set[c >> 3] = (uint8_t)(set[c >> 3] | (1u << (c & 7)));
}

static bool is_word(unsigned c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

static bool is_space(unsigned c)
{
    return c == ' ' || (c >= '\t' && c <= '\r');
}

/* Adds \d \w \s (or their negations, over all bytes) to `set`; false if `e` is no class escape. */
static bool add_class_escape(uint8_t *set, char e)
{
    char lower = (char)(e | 0x20);
    if (lower != 'd' && lower != 'w' && lower != 's') {
        return false;
    }
    bool negated = e != lower;
    for (unsigned c = 0; c < 256; ++c) {
        bool in = lower == 'd' ? (c >= '0' && c <= '9') : lower == 'w' ? is_word(c) : is_space(c);
        if (in != negated) {
            set_bit(set, c);
        }
    }
    return true;
}

static int hex_value(char c)
{
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    c = (char)(c | 0x20);
    return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

/* After a backslash (not a class escape): the byte it stands for, or -1 with ps->error set.
 * Unknown escapes are identity escapes, as in JavaScript without the u flag. */
static int escaped_char(parser *ps, bool in_class)
{
    char e = *ps->p++;
    switch (e) {
    case '\0':
        fail(ps, UBII_ERR_INVALID_ARGUMENT);
        return -1;
    case 't':
        return '\t';
    case 'n':
        return '\n';
    case 'r':
        return '\r';
    case 'f':
        return '\f';
    case 'v':
        return '\v';
    case '0':
        return 0;
    case 'b':
        return in_class ? '\b' : 'b';
    case 'c':
        if ((*ps->p | 0x20) >= 'a' && (*ps->p | 0x20) <= 'z') {
            return *ps->p++ & 31;
        }
        ps->p--; /* "\c" not followed by a letter is a literal backslash */
        return '\\';
    case 'x':
    case 'u': {
        int digits = e == 'x' ? 2 : 4;
        int value = 0;
        for (int i = 0; i < digits; ++i) {
            int h = hex_value(ps->p[i]);
            if (h < 0) {
                return e; /* not an escape sequence: the letter itself */
            }
            value = value * 16 + h;
        }
        if (value > 0x7f) {
            fail(ps, UBII_ERR_UNSUPPORTED);
            return -1;
        }
        ps->p += digits;
        return value;
    }
    default:
        if (e >= '1' && e <= '9' && !in_class) {
            fail(ps, UBII_ERR_UNSUPPORTED); /* back-reference */
            return -1;
        }
        if ((unsigned char)e >= 0x80) {
            fail(ps, UBII_ERR_UNSUPPORTED);
            return -1;
        }
        return (unsigned char)e;
    }
}

/* One class member: a byte (returned), or a class escape (added to set, returns -2). */
static int class_atom(parser *ps, uint8_t *set)
{
    unsigned char c = (unsigned char)*ps->p;
    if (c >= 0x80) {
        fail(ps, UBII_ERR_UNSUPPORTED);
        return -1;
    }
    ps->p++;
    if (c != '\\') {
        return c;
    }
    if (add_class_escape(set, *ps->p)) {
        ps->p++;
        return -2;
    }
    return escaped_char(ps, true);
}

static bool parse_class(parser *ps)
{
    program *prog = ps->prog;
    if (prog->class_count >= UBII_REGEX_MAX_CLASSES) {
        return fail(ps, UBII_ERR_TOO_LARGE);
    }
    uint8_t set[32];
    memset(set, 0, sizeof set);
    bool negated = *ps->p == '^';
    if (negated) {
        ps->p++;
    }
    /* In JavaScript "[]" matches nothing and "[^]" anything: ']' first closes the class. */
    while (*ps->p != ']') {
        if (*ps->p == '\0') {
            return fail(ps, UBII_ERR_INVALID_ARGUMENT);
        }
        int low = class_atom(ps, set);
        if (low == -1) {
            return false;
        }
        if (*ps->p == '-' && ps->p[1] != ']' && ps->p[1] != '\0' && low != -2) {
            const char *dash = ps->p++;
            uint8_t scratch[32];
            memset(scratch, 0, sizeof scratch);
            int high = class_atom(ps, scratch);
            if (high == -1) {
                return false;
            }
            if (high == -2) { /* "a-\d": the '-' is literal */
                set_bit(set, (unsigned)low);
                set_bit(set, '-');
                for (size_t i = 0; i < sizeof set; ++i) {
                    set[i] = (uint8_t)(set[i] | scratch[i]);
                }
                continue;
            }
            if (high < low) {
                ps->p = dash;
                return fail(ps, UBII_ERR_INVALID_ARGUMENT); /* range out of order */
            }
            for (int c = low; c <= high; ++c) {
                set_bit(set, (unsigned)c);
            }
        } else if (low >= 0) {
            set_bit(set, (unsigned)low);
        }
    }
    ps->p++;
    if (negated) {
        for (size_t i = 0; i < sizeof set; ++i) {
            set[i] = (uint8_t)~set[i];
        }
    }
    memcpy(prog->classes[prog->class_count], set, sizeof set);
    return emit(ps, OP_CLASS, (uint8_t)prog->class_count++, 0, 0);
}

/* ---- the grammar
 * --------------------------------------------------------------------------------- */

static bool parse_alternation(parser *ps);

/* {n}, {n,}, {n,m}: true and the bounds if the text at ps->p is one (m = -1: unbounded). */
static bool read_braces(const char *p, int *min, int *max, const char **end)
{
    if (*p++ != '{' || *p < '0' || *p > '9') {
        return false;
    }
    long low = 0;
    while (*p >= '0' && *p <= '9') {
        low = low * 10 + (*p++ - '0');
        if (low > 100000) {
            low = 100000;
        }
    }
    long high = low;
    if (*p == ',') {
        p++;
        high = -1;
        if (*p >= '0' && *p <= '9') {
            high = 0;
            while (*p >= '0' && *p <= '9') {
                high = high * 10 + (*p++ - '0');
                if (high > 100000) {
                    high = 100000;
                }
            }
        }
    }
    if (*p != '}') {
        return false;
    }
    *min = (int)low;
    *max = (int)high;
    *end = p + 1;
    return true;
}

static bool parse_atom(parser *ps)
{
    unsigned char c = (unsigned char)*ps->p;
    int min, max;
    const char *end;
    switch (c) {
    case '(':
        ps->p++;
        if (*ps->p == '?') {
            if (ps->p[1] != ':') {
                return fail(ps, UBII_ERR_UNSUPPORTED); /* lookaround, named groups */
            }
            ps->p += 2;
        }
        if (!parse_alternation(ps)) {
            return false;
        }
        if (*ps->p != ')') {
            return fail(ps, UBII_ERR_INVALID_ARGUMENT);
        }
        ps->p++;
        return true;
    case ')':
    case '*':
    case '+':
    case '?':
        return fail(ps, UBII_ERR_INVALID_ARGUMENT); /* unmatched ')' or nothing to repeat */
    case '{':
        if (read_braces(ps->p, &min, &max, &end)) {
            return fail(ps, UBII_ERR_INVALID_ARGUMENT);
        }
        ps->p++;
        return emit(ps, OP_CHAR, '{', 0, 0);
    case '[':
        ps->p++;
        return parse_class(ps);
    case '.':
        ps->p++;
        return emit(ps, OP_ANY, 0, 0, 0);
    case '^':
        ps->p++;
        return emit(ps, OP_BOL, 0, 0, 0);
    case '$':
        ps->p++;
        return emit(ps, OP_EOL, 0, 0, 0);
    case '\\': {
        ps->p++;
        char e = *ps->p;
        if (e == 'b' || e == 'B') {
            ps->p++;
            return emit(ps, e == 'b' ? OP_WORDB : OP_NWORDB, 0, 0, 0);
        }
        uint8_t set[32];
        memset(set, 0, sizeof set);
        if (add_class_escape(set, e)) {
            if (ps->prog->class_count >= UBII_REGEX_MAX_CLASSES) {
                return fail(ps, UBII_ERR_TOO_LARGE);
            }
            ps->p++;
            memcpy(ps->prog->classes[ps->prog->class_count], set, sizeof set);
            return emit(ps, OP_CLASS, (uint8_t)ps->prog->class_count++, 0, 0);
        }
        int value = escaped_char(ps, false);
        return value >= 0 && emit(ps, OP_CHAR, (uint8_t)value, 0, 0);
    }
    default:
        ps->p++;
        if (!emit(ps, OP_CHAR, c, 0, 0)) {
            return false;
        }
        /* The continuation bytes of a UTF-8 character belong to the same atom. */
        while (c >= 0xc0 && ((unsigned char)*ps->p & 0xc0) == 0x80) {
            if (!emit(ps, OP_CHAR, (uint8_t)*ps->p++, 0, 0)) {
                return false;
            }
        }
        return true;
    }
}

/* Wraps code[start, end) in `x?`, or (end being the program's end) in `x*`. */
static bool make_optional(parser *ps, int start, int end, bool repeat)
{
    if (!insert(ps, start, OP_SPLIT, 1, 0)) { /* SPLIT +1, after; x; after: */
        return false;
    }
    end++;
    if (repeat) { /* ...; x; JMP back to the SPLIT */
        if (!emit(ps, OP_JMP, 0, start - ps->prog->length, 0)) {
            return false;
        }
        end++;
    }
    ps->prog->code[start].y = (int16_t)(end - start);
    return true;
}

static bool parse_repeat(parser *ps)
{
    int start = ps->prog->length;
    if (!parse_atom(ps)) {
        return false;
    }
    int min, max;
    const char *end;
    char q = *ps->p;
    if (q == '*' || q == '+' || q == '?') {
        ps->p++;
        min = q == '+' ? 1 : 0;
        max = q == '?' ? 1 : -1;
    } else if (q == '{' && read_braces(ps->p, &min, &max, &end)) {
        ps->p = end;
        if ((max >= 0 && max < min) || min > MAX_REPEAT || max > MAX_REPEAT) {
            return fail(ps, max >= 0 && max < min ? UBII_ERR_INVALID_ARGUMENT : UBII_ERR_TOO_LARGE);
        }
    } else {
        return true;
    }
    if (*ps->p == '?') {
        ps->p++; /* lazy: same topics match */
    }
    int size = ps->prog->length - start;
    if (min == 0 && max == 0) {
        ps->prog->length = start;
        return true;
    }
    /* x{min,max}: min copies, then either x* or (max - min) times x? */
    for (int i = 1; i < min; ++i) {
        if (!copy_block(ps, start, size)) {
            return false;
        }
    }
    if (max < 0) {
        if (min == 0) {
            return make_optional(ps, start, ps->prog->length, true);
        }
        /* x+ : x; SPLIT back, +1 */
        int last = ps->prog->length - size;
        return emit(ps, OP_SPLIT, 0, last - ps->prog->length, 1);
    }
    /* The optional copies are taken from the untouched original at `start`; with min == 0 the
     * original itself is the first optional one, wrapped last so that no copy sees the wrapping. */
    for (int i = min > 0 ? min : 1; i < max; ++i) {
        int copy_start = ps->prog->length;
        if (!copy_block(ps, start, size) ||
            !make_optional(ps, copy_start, copy_start + size, false)) {
            return false;
        }
    }
    return min > 0 || make_optional(ps, start, start + size, false);
}

static bool parse_sequence(parser *ps)
{
    while (*ps->p != '\0' && *ps->p != '|' && *ps->p != ')') {
        if (!parse_repeat(ps)) {
            return false;
        }
    }
    return true;
}

static bool parse_alternation(parser *ps)
{
    int start = ps->prog->length;
    if (!parse_sequence(ps)) {
        return false;
    }
    while (*ps->p == '|') {
        ps->p++;
        /* SPLIT +1, right; left; JMP end; right: ...; end: */
        if (!insert(ps, start, OP_SPLIT, 1, 0)) {
            return false;
        }
        int jump = ps->prog->length;
        if (!emit(ps, OP_JMP, 0, 0, 0)) {
            return false;
        }
        ps->prog->code[start].y = (int16_t)(ps->prog->length - start);
        if (!parse_sequence(ps)) {
            return false;
        }
        ps->prog->code[jump].x = (int16_t)(ps->prog->length - jump);
    }
    return true;
}

static ubii_status compile(const char *pattern, program *prog)
{
    parser ps = {pattern, prog, UBII_OK};
    prog->length = 0;
    prog->class_count = 0;
    if (!parse_alternation(&ps)) {
        return ps.error;
    }
    if (*ps.p != '\0') {
        return UBII_ERR_INVALID_ARGUMENT; /* unmatched ')' */
    }
    return emit(&ps, OP_MATCH, 0, 0, 0) ? UBII_OK : ps.error;
}

/* ---- the automaton
 * --------------------------------------------------------------------------------- */

typedef struct thread_list {
    int16_t pcs[UBII_REGEX_MAX_PROGRAM];
    int count;
} thread_list;

typedef struct matcher {
    const program *prog;
    const unsigned char *text;
    size_t length;
    uint32_t marks[UBII_REGEX_MAX_PROGRAM];
    uint32_t generation;
    uint32_t steps;
    uint32_t step_limit;
    bool matched;
    bool exhausted;
} matcher;

static bool word_at(const matcher *m, size_t pos)
{
    return pos < m->length && is_word(m->text[pos]);
}

/* Follows jumps, splits and assertions from `pc` at text position `pos`, adding the consuming
 * instructions reached to `list`. Iterative, with an explicit stack bounded by the program. */
static void add_thread(matcher *m, thread_list *list, int pc, size_t pos)
{
    int16_t stack[UBII_REGEX_MAX_PROGRAM];
    int depth = 0;
    stack[depth++] = (int16_t)pc;
    while (depth > 0) {
        int at = stack[--depth];
        if (m->marks[at] == m->generation) {
            continue;
        }
        m->marks[at] = m->generation;
        if (++m->steps > m->step_limit) {
            m->exhausted = true;
            return;
        }
        const inst *i = &m->prog->code[at];
        bool boundary;
        switch (i->op) {
        case OP_JMP:
            stack[depth++] = (int16_t)(at + i->x);
            break;
        case OP_SPLIT: /* each instruction is marked once, so the stack cannot overflow */
            stack[depth++] = (int16_t)(at + i->y);
            stack[depth++] = (int16_t)(at + i->x);
            break;
        case OP_BOL:
            if (pos == 0) {
                stack[depth++] = (int16_t)(at + 1);
            }
            break;
        case OP_EOL:
            if (pos == m->length) {
                stack[depth++] = (int16_t)(at + 1);
            }
            break;
        case OP_WORDB:
        case OP_NWORDB:
            boundary = (pos > 0 && word_at(m, pos - 1)) != word_at(m, pos);
            if (boundary == (i->op == OP_WORDB)) {
                stack[depth++] = (int16_t)(at + 1);
            }
            break;
        case OP_MATCH:
            m->matched = true;
            return;
        default:
            list->pcs[list->count++] = (int16_t)at;
            break;
        }
    }
}

static bool consumes(const program *prog, const inst *i, unsigned char c)
{
    switch (i->op) {
    case OP_CHAR:
        return c == i->c;
    case OP_ANY:
        return c != '\n' && c != '\r';
    case OP_CLASS:
        return (prog->classes[i->c][c >> 3] >> (c & 7)) & 1;
    default:
        return false;
    }
}

ubii_status ubii__regex_search(const char *pattern, const char *text, uint32_t step_limit)
{
    if (pattern == NULL || text == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    program prog;
    ubii_status status = compile(pattern, &prog);
    if (status != UBII_OK) {
        return status;
    }
    matcher m;
    memset(&m, 0, sizeof m);
    m.prog = &prog;
    m.text = (const unsigned char *)text;
    m.length = strlen(text);
    m.step_limit = step_limit;

    thread_list lists[2];
    thread_list *current = &lists[0];
    thread_list *next = &lists[1];
    current->count = 0;
    for (size_t pos = 0;; ++pos) {
        m.generation++;
        /* Unanchored: a match may start at every position. Threads already here keep priority,
         * which does not matter for a yes/no answer. */
        for (int t = 0; t < current->count; ++t) {
            m.marks[current->pcs[t]] = m.generation;
        }
        add_thread(&m, current, 0, pos);
        if (m.matched) {
            return UBII_OK;
        }
        if (m.exhausted) {
            return UBII_ERR_TIMEOUT;
        }
        if (pos == m.length) {
            return UBII_ERR_NOT_FOUND;
        }
        m.generation++;
        next->count = 0;
        for (int t = 0; t < current->count; ++t) {
            const inst *i = &prog.code[current->pcs[t]];
            if (consumes(&prog, i, m.text[pos])) {
                add_thread(&m, next, current->pcs[t] + 1, pos + 1);
                if (m.matched) {
                    return UBII_OK;
                }
                if (m.exhausted) {
                    return UBII_ERR_TIMEOUT;
                }
            }
        }
        thread_list *swap = current;
        current = next;
        next = swap;
    }
}

ubii_status ubii__regex_validate(const char *pattern)
{
    program prog;
    return pattern != NULL ? compile(pattern, &prog) : UBII_ERR_INVALID_ARGUMENT;
}

ubii_status ubii_regex_search(const char *regex, const char *topic)
{
    return ubii__regex_search(regex, topic, UBII_REGEX_STEP_LIMIT);
}
