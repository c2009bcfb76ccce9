# Sourced by the scripts that play one match of two carrom-bot processes, a creator and a
# joiner, whose JSON summaries go to DIR/creator.json and DIR/joiner.json and whose stderr to
# DIR/creator.err and DIR/joiner.err (scripts/netns_match_test.sh, scripts/cluster.sh). The
# caller defines fail MESSAGE (print and exit 1).
. "$(dirname "${BASH_SOURCE[0]}")/wait_for_output.sh"

# bot_pair_room_code DIR PID: the room code the creator (process PID) prints on stderr
# ("room CODE"), waited for up to 10 s; empty when none came or the creator ended.
bot_pair_room_code() {
    wait_for_output "$1/creator.err" 's/^room \([A-Z0-9]\{6\}\)$/\1/p' "$2"
}

# bot_pair_field FILE NAME: a top-level field of a bot's JSON summary, as compact JSON.
bot_pair_field() {
    python3 -c 'import json,sys; print(json.dumps(json.load(open(sys.argv[1]))[sys.argv[2]]))' "$1" "$2"
}

# bot_pair_check DIR: both bots ended well ("ok": true) and agree on the scores; fail otherwise.
bot_pair_check() {
    local bot
    for bot in creator joiner; do
        [[ $(bot_pair_field "$1/$bot.json" ok) == true ]] || fail "$bot: $(cat "$1/$bot.json")"
    done
    [[ "$(bot_pair_field "$1/creator.json" scores)" == "$(bot_pair_field "$1/joiner.json" scores)" ]] ||
        fail "the bots disagree on the score: $(cat "$1/creator.json" "$1/joiner.json")"
}
