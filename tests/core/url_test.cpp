// ubii_url_parse: the one URL reader of the core and both ports.
#include <string>

#include <gtest/gtest.h>

#include "ubii/url.h"

namespace
{

std::string host_of(const ubii_url &url)
{
    return std::string(url.host, url.host_length);
}

TEST(Url, SplitsSchemeHostPortAndPath)
{
    ubii_url url;
    ASSERT_EQ(ubii_url_parse("http://master.local:8102/services/binary", &url), UBII_OK);
    EXPECT_EQ(url.scheme, UBII_URL_HTTP);
    EXPECT_FALSE(url.tls);
    EXPECT_EQ(host_of(url), "master.local");
    EXPECT_EQ(url.port, 8102);
    EXPECT_STREQ(url.path, "/services/binary");
}

TEST(Url, TakesTheSchemesDefaultPortAndAQueryWithoutPath)
{
    ubii_url url;
    ASSERT_EQ(ubii_url_parse("wss://example.org?clientID=x", &url), UBII_OK);
    EXPECT_EQ(url.scheme, UBII_URL_WSS);
    EXPECT_TRUE(url.tls);
    EXPECT_EQ(url.port, 443);
    EXPECT_STREQ(url.path, "?clientID=x");
    ASSERT_EQ(ubii_url_parse("ws://10.0.0.2", &url), UBII_OK);
    EXPECT_EQ(url.port, 80);
    EXPECT_STREQ(url.path, "");
}

TEST(Url, ReadsAnIpv6HostWithoutItsBrackets)
{
    ubii_url url;
    ASSERT_EQ(ubii_url_parse("tcp://[::1]:8101", &url), UBII_OK);
    EXPECT_EQ(url.scheme, UBII_URL_TCP);
    EXPECT_EQ(host_of(url), "::1");
    EXPECT_EQ(url.port, 8101);
}

TEST(Url, LeavesAnUnknownSchemeToThePort)
{
    ubii_url url;
    ASSERT_EQ(ubii_url_parse("gopher://127.0.0.1:70/1", &url), UBII_OK);
    EXPECT_EQ(url.scheme, UBII_URL_OTHER);
    EXPECT_EQ(url.port, 70);
}

TEST(Url, RefusesWhatIsNotAUrlOfTheForm)
{
    ubii_url url;
    for (const char *bad :
         {"", "no-scheme", "://host:1", "tcp://", "tcp://host", "tcp://host:1/path", "tcp://host:0",
          "tcp://host:65536", "tcp://host:12x", "http://:80/", "http://[::1/", "http://[::1]x/",
          "ht tp://host/", "tcp://host:99999999999999999999", "http://[a/b]:80/", "http://ho st/",
          "http://host/\tpath"}) {
        EXPECT_EQ(ubii_url_parse(bad, &url), UBII_ERR_INVALID_ARGUMENT) << bad;
    }
    EXPECT_EQ(ubii_url_parse(nullptr, &url), UBII_ERR_INVALID_ARGUMENT);
    EXPECT_EQ(ubii_url_parse("tcp://host:1", nullptr), UBII_ERR_INVALID_ARGUMENT);
}

TEST(Url, AcceptsTheHighestPort)
{
    ubii_url url;
    ASSERT_EQ(ubii_url_parse("tcp://host:65535", &url), UBII_OK);
    EXPECT_EQ(url.port, 65535);
}

} // namespace
