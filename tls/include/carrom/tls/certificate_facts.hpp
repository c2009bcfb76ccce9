#pragma once
// What the programs say about an X.509 certificate: its subject, serial number, validity and
// the names it is for. No OpenSSL in this header.

#include <cstdint>
#include <string>
#include <vector>

struct x509_st; // OpenSSL's X509

namespace carrom::tls {

struct CertificateFacts {
    std::string subject;             // RFC 2253, e.g. "CN=play.example.org"
    std::string serial;              // upper-case hexadecimal, e.g. "1A2B"
    std::string not_before;          // UTC, ISO 8601: "2026-11-28T11:00:00Z"
    std::string not_after;           // UTC, ISO 8601
    std::int64_t not_after_unix = 0; // seconds since 1970 (UTC)
    std::vector<std::string> names;  // subjectAltName DNS names and IP addresses, in order
};

CertificateFacts certificate_facts(const x509_st* certificate);

// "localhost, 127.0.0.1" (the subject when the certificate has no subjectAltName).
std::string names_text(const CertificateFacts& facts);

} // namespace carrom::tls
