"""The query language's grammar (lark, LALR).

Edit it here, then run `python scripts/make_query_parser.py` to regenerate
`_query_parser.py`; a test fails while the two disagree.
"""

GRAMMAR = r"""
?start: or_expr
?or_expr: and_expr (_OR and_expr)*
?and_expr: not_expr (_AND not_expr)*
?not_expr: _NOT not_expr -> negation
         | atom
?atom: "(" or_expr ")"
     | comparison
     | between
comparison: field OP value
between: field _BETWEEN value _AND value
field: NAME ("." NAME)*
value: NUMBER (UNIT NUMBER)* UNIT?   -> number
     | NAME                          -> word
     | STRING                        -> quoted
     | UNKNOWN                       -> unknown
_OR.3: /or\b/i
_AND.3: /and\b/i
_NOT.3: /not\b/i
_BETWEEN.3: /between\b/i
OP: "<=" | ">=" | "!=" | "<>" | "<" | ">" | "=" | "≤" | "≥" | "≠"
NAME.2: /[A-Za-z_][A-Za-z0-9_]*/
STRING: /'[^']*'|"[^"]*"/
UNKNOWN: "?"
NUMBER: /[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?/
UNIT: /(ft|lbf?|N|n)[-·*]?(lbf?|lbs|m|ft)\b|deg\/s|rad\/s|°\/s|[A-Za-z°"]+/
%import common.WS
%ignore WS
"""
