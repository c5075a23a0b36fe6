#include "net/invitation.h"

#include "farm/build_info.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

TEST(InvitationTest, TheRightSecretAndVersionAreAdmittedAndNothingElse) {
  const Secret secret = newSecret();
  EXPECT_NE(secret, newSecret()) << "secrets are random";
  const Challenge challenge = newChallenge();
  const std::string build = buildDescription();
  std::string host;
  EXPECT_EQ(checkProof(secret, challenge, proofFor(secret, challenge, build, "host-a"), &host), "");
  EXPECT_EQ(host, "host-a");
  // Another secret, another challenge (a replayed proof), no proof, a tampered version.
  EXPECT_NE(checkProof(secret, challenge, proofFor(newSecret(), challenge, build, "host-a")), "");
  EXPECT_NE(checkProof(secret, newChallenge(), proofFor(secret, challenge, build, "host-a")), "");
  EXPECT_NE(checkProof(secret, challenge, {}), "");
  std::vector<uint8_t> tampered = proofFor(secret, challenge, build, "host-a");
  tampered.back() ^= 1;
  EXPECT_NE(checkProof(secret, challenge, tampered), "");
  // Another version, with the right secret: refused, and said so.
  const std::string why = checkProof(secret, challenge, proofFor(secret, challenge, "prt 9.9.9 (trace kernels: baseline)", "host-a"));
  EXPECT_NE(why.find("prt 9.9.9"), std::string::npos) << why;
  // The same version on other trace kernels: admitted (every build renders the same bits).
  EXPECT_EQ(checkProof(secret, challenge,
                       proofFor(secret, challenge, "prt " + prtVersion() + " (trace kernels: baseline)", "host-a")),
            "");
}

TEST(InvitationTest, ThePortFileCarriesThePortAndTheSecret) {
  const Secret secret = newSecret();
  const PortFile read = parsePortFile(portFileText("tag#0$port#1234$", secret));
  EXPECT_EQ(read.port, "tag#0$port#1234$");
  ASSERT_TRUE(read.secret.has_value());
  EXPECT_EQ(*read.secret, secret);
  // A port file of an older render (the port alone), or a damaged secret: no secret.
  EXPECT_FALSE(parsePortFile("tag#0$port#1234$\n").secret.has_value());
  EXPECT_FALSE(parsePortFile("p\nsecret 12zz\n").secret.has_value());
  EXPECT_EQ(secretFromHex(secretHex(secret)), secret);
}

}  // namespace
}  // namespace prt
