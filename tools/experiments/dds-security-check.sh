#!/usr/bin/env bash
# DDS Security with Debian 12's Cyclone DDS 0.10.2 (docs/dds-trust.md): makes a throwaway CA,
# a node identity and a read-only display identity, governance and permissions documents, and
# Cyclone XMLs that add the Security section to the loopback configuration; starts skytrackd
# as the node, then checks that the node's `skytrack bench-latency` and `skytrack status` get
# answers, the display's `status` too but not its attempt to publish plots, and that an
# unauthenticated `skytrack status` (the shipped loopback.xml) finds nothing. Loopback only.
# Usage: tools/experiments/dds-security-check.sh   (needs openssl; exit 0 when all hold)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${SKYTRACK_BUILD_DIR:-$root/build}
skytrack="$build/tools/skytrack/skytrack"
skytrackd="$build/tools/skytrackd/skytrackd"
plugins=/usr/lib/x86_64-linux-gnu/libddsc0debian  # Debian keeps the plugins here, off the path
domain=230                                       # the governance below covers 0..230
work=$(mktemp -d)
daemon=""
cleanup() { [ -n "$daemon" ] && kill "$daemon" 2>/dev/null; wait 2>/dev/null || true; rm -rf "$work"; }
trap cleanup EXIT
cd "$work"

# Identity CA (also the permissions CA here), a node identity and a read-only display identity.
openssl ecparam -name prime256v1 -genkey -noout -out ca.key
openssl req -new -x509 -key ca.key -out ca.pem -days 3650 -subj "/C=NL/O=skytrack/CN=skytrack CA"
for who in node display; do
  openssl ecparam -name prime256v1 -genkey -noout -out $who.key
  openssl req -new -key $who.key -out $who.csr -subj "/C=NL/O=skytrack/CN=skytrack $who"
  openssl x509 -req -in $who.csr -CA ca.pem -CAkey ca.key -CAcreateserial -out $who.pem \
    -days 3650 2>/dev/null
done

cat >governance.xml <<'EOF'
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="omg_shared_ca_governance.xsd">
  <domain_access_rules>
    <domain_rule>
      <domains><id_range><min>0</min><max>230</max></id_range></domains>
      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>
      <enable_join_access_control>true</enable_join_access_control>
      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>
      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>
      <rtps_protection_kind>SIGN</rtps_protection_kind>
      <topic_access_rules>
        <topic_rule>
          <topic_expression>*</topic_expression>
          <enable_discovery_protection>true</enable_discovery_protection>
          <enable_liveliness_protection>true</enable_liveliness_protection>
          <enable_read_access_control>true</enable_read_access_control>
          <enable_write_access_control>true</enable_write_access_control>
          <metadata_protection_kind>ENCRYPT</metadata_protection_kind>
          <data_protection_kind>ENCRYPT</data_protection_kind>
        </topic_rule>
      </topic_access_rules>
    </domain_rule>
  </domain_access_rules>
</dds>
EOF
cat >permissions.xml <<'EOF'
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="omg_shared_ca_permissions.xsd">
  <permissions>
    <grant name="skytrack_node">
      <subject_name>CN=skytrack node,O=skytrack,C=NL</subject_name>
      <validity><not_before>2024-01-01T00:00:00</not_before><not_after>2034-01-01T00:00:00</not_after></validity>
      <allow_rule>
        <domains><id_range><min>0</min><max>230</max></id_range></domains>
        <publish><topics><topic>skytrack_*</topic></topics></publish>
        <subscribe><topics><topic>skytrack_*</topic></topics></subscribe>
      </allow_rule>
      <default>DENY</default>
    </grant>
    <grant name="display">
      <subject_name>CN=skytrack display,O=skytrack,C=NL</subject_name>
      <validity><not_before>2024-01-01T00:00:00</not_before><not_after>2034-01-01T00:00:00</not_after></validity>
      <allow_rule>
        <domains><id_range><min>0</min><max>230</max></id_range></domains>
        <subscribe><topics><topic>skytrack_*</topic></topics></subscribe>
      </allow_rule>
      <default>DENY</default>
    </grant>
  </permissions>
</dds>
EOF
openssl smime -sign -in governance.xml -text -out governance.p7s -signer ca.pem -inkey ca.key
openssl smime -sign -in permissions.xml -text -out permissions.p7s -signer ca.pem -inkey ca.key

# The shipped loopback configuration plus the Security section.
sed "s|</Discovery>|</Discovery>\n    <Security>\n\
      <Authentication>\n\
        <Library path=\"$plugins/libdds_security_auth.so\" initFunction=\"init_authentication\" finalizeFunction=\"finalize_authentication\"/>\n\
        <IdentityCA>file:$work/ca.pem</IdentityCA>\n\
        <IdentityCertificate>file:$work/node.pem</IdentityCertificate>\n\
        <PrivateKey>file:$work/node.key</PrivateKey>\n\
      </Authentication>\n\
      <AccessControl>\n\
        <Library path=\"$plugins/libdds_security_ac.so\" initFunction=\"init_access_control\" finalizeFunction=\"finalize_access_control\"/>\n\
        <PermissionsCA>file:$work/ca.pem</PermissionsCA>\n\
        <Governance>file:$work/governance.p7s</Governance>\n\
        <Permissions>file:$work/permissions.p7s</Permissions>\n\
      </AccessControl>\n\
      <Cryptographic>\n\
        <Library path=\"$plugins/libdds_security_crypto.so\" initFunction=\"init_crypto\" finalizeFunction=\"finalize_crypto\"/>\n\
      </Cryptographic>\n\
    </Security>|" "$root/config/dds/loopback.xml" >secure.xml
sed -e "s|^  domain: 0|  domain: $domain|" -e "s|profiles/default.yaml|$root/config/profiles/default.yaml|" \
  -e "s|level: info|level: warn|" -e "s|status_period: 1.0|status_period: 0.5|" \
  "$root/config/skytrackd.yaml" >skytrackd.yaml
sed "s|/node\.|/display.|g" secure.xml >display.xml

secure="file://$work/secure.xml"
plain="file://$root/config/dds/loopback.xml"
CYCLONEDDS_URI=$secure "$skytrackd" --config skytrackd.yaml 2>daemon.log &
daemon=$!
failed=0
echo "authenticated bench-latency:"
CYCLONEDDS_URI=$secure "$skytrack" bench-latency --config skytrackd.yaml --targets 10 --scans 100 ||
  failed=1
sleep 1.2  # the next periodic status counts the scans
echo "authenticated status:"
CYCLONEDDS_URI=$secure "$skytrack" status --config skytrackd.yaml --wait 5 >status.json || failed=1
cat status.json
grep -q '"scans_processed": 120,' status.json || failed=1
echo "display identity (subscribe only) status:"
CYCLONEDDS_URI="file://$work/display.xml" "$skytrack" status --config skytrackd.yaml --wait 5 ||
  failed=1
echo "display identity publishing plots, expected to be refused:"
if CYCLONEDDS_URI="file://$work/display.xml" "$skytrack" bench-latency --config skytrackd.yaml \
  --targets 10 --scans 10; then failed=1; fi
echo "unauthenticated status (shipped loopback.xml), expected to find nothing:"
if CYCLONEDDS_URI=$plain "$skytrack" status --config skytrackd.yaml --wait 5; then failed=1; fi
kill -TERM "$daemon"
wait "$daemon" || failed=1
daemon=""
[ -s daemon.log ] && { echo "daemon log:"; cat daemon.log; }
echo "result: $([ $failed = 0 ] && echo "all as expected" || echo FAILED)"
exit $failed
