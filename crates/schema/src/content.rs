//! Does a list of child elements fit a complex type's content model?
//!
//! The OpenSCENARIO schemas obey XSD's unique particle attribution rule, so a greedy left-to-right
//! match that looks one element ahead is exact: at each point at most one particle can take the
//! next child.

use crate::model::{ComplexType, Particle, Schema, Term};

/// What is wrong with an element's children. `child` indexes the slice given to [`match_children`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ContentProblem {
    /// A child whose name the type's content model does not have at all.
    Unknown { child: usize },
    /// A known child in a place the model does not allow: out of order, or one too many.
    NotAllowedHere { child: usize },
    /// Required children are missing: one of `expected` (a single name, or the alternatives of a choice).
    Missing { expected: Vec<String>, before: Option<usize> },
}

/// Matches `children` (element local names, in document order) against `ty`'s content model.
pub fn match_children(schema: &Schema, ty: &ComplexType, children: &[&str]) -> Vec<ContentProblem> {
    let known: Vec<&str> = schema.child_elements(ty).iter().map(|e| e.name.as_str()).collect();
    let mut problems = Vec::new();
    let mut items = Vec::new();
    for (i, name) in children.iter().enumerate() {
        if known.contains(name) {
            items.push((i, *name));
        } else {
            problems.push(ContentProblem::Unknown { child: i });
        }
    }
    let mut m = Matcher { schema, items: &items, pos: 0, problems: &mut problems };
    if let Some(content) = &ty.content {
        m.particle(content, 0);
    }
    for &(i, _) in &items[m.pos..] {
        m.problems.push(ContentProblem::NotAllowedHere { child: i });
    }
    problems.sort_by_key(|p| match p {
        ContentProblem::Unknown { child } | ContentProblem::NotAllowedHere { child } => *child,
        ContentProblem::Missing { before, .. } => before.unwrap_or(usize::MAX),
    });
    problems
}

/// Guards against a schema whose groups refer to each other in a cycle.
const MAX_DEPTH: usize = 64;

struct Matcher<'a> {
    schema: &'a Schema,
    items: &'a [(usize, &'a str)],
    pos: usize,
    problems: &'a mut Vec<ContentProblem>,
}

impl Matcher<'_> {
    fn next(&self) -> Option<&str> {
        self.items.get(self.pos).map(|(_, n)| *n)
    }

    fn particle(&mut self, p: &Particle, depth: usize) {
        if depth > MAX_DEPTH {
            return;
        }
        let mut reps = 0u32;
        while p.max.is_none_or(|m| reps < m) {
            let Some(next) = self.next() else { break };
            if !self.first(&p.term, depth).contains(&next) {
                break;
            }
            let before = self.pos;
            self.term(&p.term, depth);
            if self.pos == before {
                break;
            }
            reps += 1;
        }
        if reps < p.min && !self.nullable_term(&p.term, depth) {
            self.require(&p.term, depth);
        }
    }

    fn term(&mut self, term: &Term, depth: usize) {
        match term {
            Term::Element(_) => self.pos += 1,
            Term::Sequence(items) => {
                for i in items {
                    self.particle(i, depth + 1);
                }
            }
            Term::Choice(items) => {
                let Some(next) = self.next() else { return };
                if let Some(alt) = items.iter().find(|i| self.first(&i.term, depth).contains(&next)) {
                    self.particle(alt, depth + 1);
                }
            }
            Term::All(items) => {
                let mut counts = vec![0u32; items.len()];
                while let Some(next) = self.next() {
                    let found = items.iter().enumerate().find(|(k, i)| i.max.is_none_or(|m| counts[*k] < m) && self.first(&i.term, depth).contains(&next));
                    let Some((k, item)) = found else { break };
                    let before = self.pos;
                    self.term(&item.term, depth + 1);
                    if self.pos == before {
                        break;
                    }
                    counts[k] += 1;
                }
                for (k, item) in items.iter().enumerate() {
                    if counts[k] < item.min && !self.nullable_term(&item.term, depth) {
                        self.require(&item.term, depth + 1);
                    }
                }
            }
            Term::Group(name) => {
                if let Some(g) = self.schema.group(name) {
                    self.term(&g.term, depth + 1);
                }
            }
        }
    }

    /// Reports a required term that is absent.
    fn require(&mut self, term: &Term, depth: usize) {
        if depth > MAX_DEPTH {
            return;
        }
        let before = self.items.get(self.pos).map(|(i, _)| *i);
        match term {
            Term::Element(e) => self.problems.push(ContentProblem::Missing { expected: vec![e.name.clone()], before }),
            Term::Sequence(items) | Term::All(items) => {
                for i in items.iter().filter(|i| i.min > 0) {
                    if !self.nullable_term(&i.term, depth) {
                        self.require(&i.term, depth + 1);
                    }
                }
            }
            Term::Choice(_) => {
                let expected = self.first(term, depth).into_iter().map(str::to_string).collect();
                self.problems.push(ContentProblem::Missing { expected, before });
            }
            Term::Group(name) => {
                if let Some(g) = self.schema.group(name) {
                    let g = g.clone();
                    self.require(&g.term, depth + 1);
                }
            }
        }
    }

    /// The element names that can start `term`.
    fn first<'s>(&'s self, term: &'s Term, depth: usize) -> Vec<&'s str> {
        let mut out = Vec::new();
        if depth > MAX_DEPTH {
            return out;
        }
        match term {
            Term::Element(e) => out.push(e.name.as_str()),
            Term::Sequence(items) => {
                for i in items {
                    out.extend(self.first(&i.term, depth + 1));
                    if i.min > 0 && !self.nullable_term(&i.term, depth + 1) {
                        break;
                    }
                }
            }
            Term::Choice(items) | Term::All(items) => {
                for i in items {
                    out.extend(self.first(&i.term, depth + 1));
                }
            }
            Term::Group(name) => {
                if let Some(g) = self.schema.group(name) {
                    out.extend(self.first(&g.term, depth + 1));
                }
            }
        }
        out
    }

    fn nullable_term(&self, term: &Term, depth: usize) -> bool {
        if depth > MAX_DEPTH {
            return true;
        }
        let nullable = |p: &Particle| p.min == 0 || self.nullable_term(&p.term, depth + 1);
        match term {
            Term::Element(_) => false,
            Term::Sequence(items) | Term::All(items) => items.iter().all(nullable),
            Term::Choice(items) => items.iter().any(nullable),
            Term::Group(name) => self.schema.group(name).is_none_or(nullable),
        }
    }
}
