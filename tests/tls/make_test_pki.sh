#!/usr/bin/env bash
# Makes the certificates the TLS tests use, with the openssl command, in DIR (created):
#   ca.pem, ca.key            the test CA the clients are given (--ca-file, Chromium's NSS db)
#   server.pem, server.key    for localhost and 127.0.0.1, serial 1001, signed by the CA
#   renewed.pem, renewed.key  the same names, serial 1002 (SIGHUP with a new certificate)
#   localhost.pem, .key       for localhost only (a client asking for 127.0.0.1 refuses it)
#   expired.pem, expired.key  for localhost and 127.0.0.1, valid 2020-01-01 to 2020-12-31
#   other-ca.pem              another CA, which signed none of these
# EC P-256 keys (fast to make). Usage: make_test_pki.sh DIR
set -euo pipefail
dir=$1
mkdir -p "$dir"
cd "$dir"
key() { openssl genpkey -algorithm EC -pkeyopt ec_paramgen_curve:P-256 -out "$1" 2>/dev/null; }

key ca.key
openssl req -x509 -new -key ca.key -subj "/CN=carrom test CA" -days 30 -out ca.pem \
    -addext "basicConstraints=critical,CA:TRUE" -addext "keyUsage=critical,keyCertSign,cRLSign"
key other-ca.key
openssl req -x509 -new -key other-ca.key -subj "/CN=carrom other CA" -days 30 -out other-ca.pem \
    -addext "basicConstraints=critical,CA:TRUE" -addext "keyUsage=critical,keyCertSign,cRLSign"

# sign NAME SERIAL SAN: NAME.key and NAME.pem for SAN, valid for 30 days from now.
sign() {
    key "$1.key"
    openssl req -new -key "$1.key" -subj "/CN=$1" -out "$1.csr"
    printf 'subjectAltName=%s\nextendedKeyUsage=serverAuth\nbasicConstraints=CA:FALSE\n' "$3" \
        > "$1.ext"
    openssl x509 -req -in "$1.csr" -CA ca.pem -CAkey ca.key -set_serial "$2" -days 30 \
        -extfile "$1.ext" -out "$1.pem" 2>/dev/null
}
sign server 0x1001 "DNS:localhost,IP:127.0.0.1"
sign renewed 0x1002 "DNS:localhost,IP:127.0.0.1"
sign localhost 0x1003 "DNS:localhost"

# An expired certificate: `openssl ca` takes explicit start and end dates.
key expired.key
openssl req -new -key expired.key -subj "/CN=expired" -out expired.csr
mkdir -p ca-db
: > ca-db/index.txt
echo 1004 > ca-db/serial
cat > ca-db/ca.cnf <<CNF
[ca]
default_ca = test
[test]
database = ca-db/index.txt
serial = ca-db/serial
new_certs_dir = ca-db
default_md = sha256
policy = any
copy_extensions = none
[any]
commonName = supplied
[server]
subjectAltName = DNS:localhost,IP:127.0.0.1
extendedKeyUsage = serverAuth
basicConstraints = CA:FALSE
CNF
openssl ca -batch -config ca-db/ca.cnf -cert ca.pem -keyfile ca.key -in expired.csr \
    -startdate 20200101000000Z -enddate 20201231000000Z -extensions server -out expired.pem \
    -notext 2>/dev/null
