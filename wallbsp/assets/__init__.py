"""wallbsp.assets"""
