/* test_schema.c — the JSON Schema subset validator: each keyword accepts what
 * it should, rejects what it should, and names the right JSON pointer. */
#include <gsl/gsl_errno.h>
#include <string.h>

#include "schema.h"
#include "testlib.h"

/* Validate instance text against schema text; return the error count and the
 * first error's pointer in ptr. */
static size_t run(const char *schema, const char *inst, char *ptr, size_t n)
{
    json_t *s = json_loads(schema, JSON_DECODE_INT_AS_REAL, NULL);
    json_t *i = json_loads(inst, JSON_DECODE_INT_AS_REAL | JSON_DECODE_ANY, NULL);
    json_t *errs = json_array();
    if (!s || !i) { fprintf(stderr, "bad test JSON\n"); return 999; }
    size_t count = api_schema_validate(s, i, "", errs);
    const char *p = json_string_value(json_object_get(json_array_get(errs, 0), "pointer"));
    snprintf(ptr, n, "%s", p ? p : "(none)");
    json_decref(s);
    json_decref(i);
    json_decref(errs);
    return count;
}

#define EXPECT(schema, inst, nerr, pointer)                                    \
    do {                                                                       \
        char p_[256];                                                          \
        size_t c_ = run(schema, inst, p_, sizeof p_);                          \
        CHECK_EQ_INT(c_, nerr);                                                \
        if ((nerr) > 0 && strcmp(p_, pointer)) {                               \
            tl_failed++;                                                       \
            fprintf(stderr, "%s:%d: pointer %s, want %s\n", __FILE__, __LINE__, p_, pointer); \
        }                                                                      \
    } while (0)

#define OBJ "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"m\"]," \
            "\"properties\":{\"m\":{\"type\":\"number\",\"exclusiveMinimum\":0}," \
            "\"n\":{\"type\":\"integer\",\"minimum\":2,\"maximum\":5}," \
            "\"v\":{\"type\":\"array\",\"items\":{\"type\":\"number\"},\"minItems\":3,\"maxItems\":3}," \
            "\"k\":{\"enum\":[\"a\",\"b\"]}," \
            "\"a/b~c\":{\"type\":\"boolean\"}}}"

int main(void)
{
    gsl_set_error_handler_off();
    EXPECT(OBJ, "{\"m\":1}", 0, "");
    EXPECT(OBJ, "{}", 1, "/m");
    EXPECT(OBJ, "[]", 1, "");
    EXPECT(OBJ, "{\"m\":0}", 1, "/m");
    EXPECT(OBJ, "{\"m\":-1e-300}", 1, "/m");
    EXPECT(OBJ, "{\"m\":\"1\"}", 1, "/m");
    EXPECT(OBJ, "{\"m\":1,\"zz\":1}", 1, "/zz");
    EXPECT(OBJ, "{\"m\":1,\"n\":2.5}", 1, "/n");
    EXPECT(OBJ, "{\"m\":1,\"n\":3}", 0, "");
    EXPECT(OBJ, "{\"m\":1,\"n\":6}", 1, "/n");
    EXPECT(OBJ, "{\"m\":1,\"v\":[1,2]}", 1, "/v");
    EXPECT(OBJ, "{\"m\":1,\"v\":[1,2,\"x\"]}", 1, "/v/2");
    EXPECT(OBJ, "{\"m\":1,\"k\":\"c\"}", 1, "/k");
    EXPECT(OBJ, "{\"m\":1,\"k\":\"b\"}", 0, "");
    EXPECT(OBJ, "{\"m\":1,\"a/b~c\":1}", 1, "/a~1b~0c");
    /* Unknown key with characters that need escaping. */
    EXPECT(OBJ, "{\"m\":1,\"x/y\":1}", 1, "/x~1y");

    /* oneOf: exactly one branch; the closest branch's errors are reported. */
    const char *one =
        "{\"oneOf\":[{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"beta\"],"
        "\"properties\":{\"beta\":{\"type\":\"number\"}}},"
        "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"gamma\",\"dir\"],"
        "\"properties\":{\"gamma\":{\"type\":\"number\",\"minimum\":1},\"dir\":{\"type\":\"number\"}}}]}";
    EXPECT(one, "{\"beta\":0.5}", 0, "");
    EXPECT(one, "{\"gamma\":2,\"dir\":1}", 0, "");
    EXPECT(one, "{\"gamma\":0.5,\"dir\":1}", 1, "/gamma");
    EXPECT(one, "{\"beta\":\"x\"}", 1, "/beta");
    /* A const discriminator picks the branch whose errors are reported, even
     * when another branch has fewer errors. */
    const char *shapes =
        "{\"oneOf\":[{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"shape\",\"r\",\"m\",\"p\"],"
        "\"properties\":{\"shape\":{\"const\":\"sphere\"},\"r\":{\"type\":\"number\"},\"m\":{},\"p\":{}}},"
        "{\"type\":\"object\",\"additionalProperties\":false,\"required\":[\"shape\"],"
        "\"properties\":{\"shape\":{\"const\":\"point\"},\"m\":{},\"p\":{}}}]}";
    EXPECT(shapes, "{\"shape\":\"sphere\",\"m\":1,\"p\":1}", 1, "/r");
    EXPECT(shapes, "{\"shape\":\"point\",\"r\":1}", 1, "/r");
    const char *both = "{\"oneOf\":[{\"type\":\"number\"},{\"minimum\":0}]}";
    EXPECT(both, "3", 1, "");

    /* type arrays, const, uniqueItems, min/maxProperties */
    EXPECT("{\"type\":[\"string\",\"null\"]}", "null", 0, "");
    EXPECT("{\"type\":[\"string\",\"null\"]}", "1", 1, "");
    EXPECT("{\"const\":\"x\"}", "\"y\"", 1, "");
    EXPECT("{\"const\":2}", "2.0", 0, "");
    EXPECT("{\"type\":\"array\",\"uniqueItems\":true}", "[\"a\",\"b\",\"a\"]", 1, "/2");
    EXPECT("{\"type\":\"object\",\"maxProperties\":1}", "{\"a\":1,\"b\":2}", 1, "");

    /* A huge array of wrong items reports a bounded number of errors. */
    {
        json_t *s = json_loads("{\"type\":\"array\",\"items\":{\"type\":\"string\"}}", 0, NULL);
        json_t *a = json_array();
        for (int i = 0; i < 100000; i++) json_array_append_new(a, json_real(i));
        json_t *errs = json_array();
        size_t c = api_schema_validate(s, a, "", errs);
        CHECK(c >= API_SCHEMA_MAX_ERRORS);
        CHECK_EQ_INT(json_array_size(errs), API_SCHEMA_MAX_ERRORS);
        json_decref(s);
        json_decref(a);
        json_decref(errs);
    }

    /* The self-check refuses unsupported keywords. */
    {
        char msg[200];
        json_t *s = json_loads("{\"type\":\"object\",\"patternProperties\":{}}", 0, NULL);
        CHECK(api_schema_check(s, msg, sizeof msg) == -1);
        CHECK(strstr(msg, "patternProperties") != NULL);
        json_decref(s);
        s = json_loads("{\"type\":\"objekt\"}", 0, NULL);
        CHECK(api_schema_check(s, msg, sizeof msg) == -1);
        json_decref(s);
        s = json_loads(OBJ, 0, NULL);
        CHECK(api_schema_check(s, msg, sizeof msg) == 0);
        json_decref(s);
    }
    TEST_MAIN_END();
}
