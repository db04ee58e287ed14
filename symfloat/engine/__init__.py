"""The checking engine: identities, witnesses, derivation checks, cache."""
