#include "carrom/tls/certificate_facts.hpp"

#include <openssl/asn1.h>
#include <openssl/bio.h>
#include <openssl/bn.h>
#include <openssl/crypto.h>
#include <openssl/x509.h>
#include <openssl/x509v3.h>

#include <cstdio>
#include <ctime>
#include <memory>

namespace carrom::tls {

namespace {

struct BioFree {
    void operator()(BIO* bio) const { BIO_free(bio); }
};

std::string name_text(const X509_NAME* name) {
    std::unique_ptr<BIO, BioFree> bio(BIO_new(BIO_s_mem()));
    if (!bio || X509_NAME_print_ex(bio.get(), name, 0, XN_FLAG_RFC2253) < 0) {
        return {};
    }
    char* data = nullptr;
    const long size = BIO_get_mem_data(bio.get(), &data);
    return size > 0 ? std::string(data, static_cast<std::size_t>(size)) : std::string();
}

// "2026-11-28T11:00:00Z" and the seconds since 1970; empty and 0 when unreadable.
std::string time_text(const ASN1_TIME* time, std::int64_t* unix_seconds) {
    std::tm tm{};
    if (time == nullptr || ASN1_TIME_to_tm(time, &tm) != 1) {
        return {};
    }
    if (unix_seconds != nullptr) {
        *unix_seconds = static_cast<std::int64_t>(timegm(&tm));
    }
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return text;
}

std::string serial_text(const ASN1_INTEGER* serial) {
    BIGNUM* number = ASN1_INTEGER_to_BN(serial, nullptr);
    if (number == nullptr) {
        return {};
    }
    char* hex = BN_bn2hex(number);
    std::string text = hex != nullptr ? hex : "";
    OPENSSL_free(hex);
    BN_free(number);
    return text;
}

std::vector<std::string> alt_names(const X509* certificate) {
    std::vector<std::string> names;
    auto* general = static_cast<GENERAL_NAMES*>(
        X509_get_ext_d2i(certificate, NID_subject_alt_name, nullptr, nullptr));
    if (general == nullptr) {
        return names;
    }
    for (int i = 0; i < sk_GENERAL_NAME_num(general); ++i) {
        const GENERAL_NAME* name = sk_GENERAL_NAME_value(general, i);
        if (name->type == GEN_DNS) {
            const auto* text = name->d.dNSName;
            names.emplace_back(reinterpret_cast<const char*>(ASN1_STRING_get0_data(text)),
                               static_cast<std::size_t>(ASN1_STRING_length(text)));
        } else if (name->type == GEN_IPADD) {
            const auto* bytes = name->d.iPAddress;
            const unsigned char* b = ASN1_STRING_get0_data(bytes);
            if (ASN1_STRING_length(bytes) == 4) {
                char text[16];
                std::snprintf(text, sizeof text, "%u.%u.%u.%u", b[0], b[1], b[2], b[3]);
                names.emplace_back(text);
            } else if (ASN1_STRING_length(bytes) == 16) {
                std::string text;
                for (int k = 0; k < 16; k += 2) {
                    char group[8];
                    std::snprintf(group, sizeof group, "%s%x", k == 0 ? "" : ":",
                                  static_cast<unsigned>(b[k] << 8 | b[k + 1]));
                    text += group;
                }
                names.push_back(text);
            }
        }
    }
    GENERAL_NAMES_free(general);
    return names;
}

} // namespace

CertificateFacts certificate_facts(const x509_st* certificate) {
    CertificateFacts facts;
    if (certificate == nullptr) {
        return facts;
    }
    facts.subject = name_text(X509_get_subject_name(certificate));
    facts.serial = serial_text(X509_get0_serialNumber(certificate));
    facts.not_before = time_text(X509_get0_notBefore(certificate), nullptr);
    facts.not_after = time_text(X509_get0_notAfter(certificate), &facts.not_after_unix);
    facts.names = alt_names(certificate);
    return facts;
}

std::string names_text(const CertificateFacts& facts) {
    if (facts.names.empty()) {
        return facts.subject;
    }
    std::string text;
    for (const auto& name : facts.names) {
        text += (text.empty() ? "" : ", ") + name;
    }
    return text;
}

} // namespace carrom::tls
